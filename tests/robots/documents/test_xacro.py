"""app.robots.documents.xacro: expanding an untrusted .urdf.xacro inside its package, bounded.

The Panda case compares Pinocchio FK of the expanded document with yourdfpy FK of the same
robot written out by hand (the catalog's Panda URDF with the tool joint appended).
"""

from __future__ import annotations

import io
import math
import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pinocchio as pin
import pytest
import yourdfpy

from app.kinematics.errors import InvalidInputError
from app.kinematics.xmldoc import XmlLimits
from app.robots.catalog import erd_share_dir
from app.robots.documents.xacro import expand_xacro

XACRO_NS = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'
PANDA = erd_share_dir() / "example-robot-data/robots/panda_description/urdf/panda.urdf"

WRAPPER = f"""<?xml version="1.0"?>
<robot name="panda" {XACRO_NS}>
  <xacro:arg name="tool_z" default="0.1"/>
  <xacro:property name="tool_z" value="$(arg tool_z)"/>
  <xacro:include filename="$(find panda_pkg)/urdf/panda.urdf"/>
  <xacro:macro name="tool" params="parent name z:=0.0 yaw:=0.0">
    <link name="${{name}}"/>
    <joint name="${{name}}_joint" type="fixed">
      <parent link="${{parent}}"/>
      <child link="${{name}}"/>
      <origin xyz="0.01 -0.02 ${{z}}" rpy="0.1 0 ${{yaw}}"/>
    </joint>
  </xacro:macro>
  <xacro:tool parent="panda_hand" name="tool0" z="${{tool_z}}" yaw="${{pi / 4}}"/>
</robot>
"""

TOOL_BY_HAND = """  <link name="tool0"/>
  <joint name="tool0_joint" type="fixed">
    <parent link="panda_hand"/>
    <child link="tool0"/>
    <origin xyz="0.01 -0.02 0.25" rpy="0.1 0 0.7853981633974483"/>
  </joint>
</robot>"""


def _package(tmp_path: Path) -> Path:
    """A package ``panda_pkg`` (package.xml, the catalog Panda URDF, the wrapper)."""
    pkg = tmp_path / "panda_pkg"
    (pkg / "urdf").mkdir(parents=True)
    (pkg / "package.xml").write_text("<package><name>panda_pkg</name></package>")
    shutil.copy(PANDA, pkg / "urdf" / "panda.urdf")
    (pkg / "urdf" / "robot.urdf.xacro").write_text(WRAPPER)
    return tmp_path


def _write(root: Path, body: str, name: str = "t.urdf.xacro") -> str:
    (root / "pkg").mkdir(parents=True, exist_ok=True)
    (root / "pkg" / name).write_text(f'<robot name="r" {XACRO_NS}>\n  {body}\n</robot>\n')
    return f"pkg/{name}"


def _refused(root: Path, description: str, **kwargs: object) -> InvalidInputError:
    args = kwargs.pop("args", {})
    with pytest.raises(InvalidInputError) as info:
        expand_xacro(root, description, args, XmlLimits(), **kwargs)  # type: ignore[arg-type]
    return info.value


def _pin_pose(model: pin.Model, data: pin.Data, q: dict[str, float], frame: str) -> np.ndarray:
    qv = pin.neutral(model)
    for jid in range(1, model.njoints):
        name = model.names[jid]
        value = q.get(name, q.get("panda_finger_joint1") if name == "panda_finger_joint2" else 0)
        qv[model.joints[jid].idx_q] = value
    pin.framesForwardKinematics(model, data, qv)
    return data.oMf[model.getFrameId(frame)].homogeneous


def test_panda_wrapper_with_include_arg_and_macro_matches_the_hand_expanded_urdf(
    tmp_path: Path,
) -> None:
    root = _package(tmp_path)
    urdf = expand_xacro(root, "panda_pkg/urdf/robot.urdf.xacro", {"tool_z": 0.25}, XmlLimits())
    by_hand = PANDA.read_text().replace("</robot>", TOOL_BY_HAND)
    ref = yourdfpy.URDF.load(io.BytesIO(by_hand.encode()), load_meshes=False)
    model = pin.buildModelFromXML(urdf)
    data = model.createData()
    assert set(ref.link_map) <= {f.name for f in model.frames}
    rng = np.random.default_rng(16)
    names = list(ref.actuated_joint_names)
    lo = np.array([ref.joint_map[n].limit.lower for n in names])
    hi = np.array([ref.joint_map[n].limit.upper for n in names])
    for _ in range(50):
        q = dict(zip(names, rng.uniform(lo, hi), strict=True))
        ref.update_cfg(q)
        for link in ("tool0", "panda_hand_tcp", "panda_rightfinger", "panda_link7"):
            expected = ref.get_transform(link, ref.base_link)
            assert np.abs(_pin_pose(model, data, q, link) - expected).max() < 1e-12, link


def test_default_arg_and_relative_include(tmp_path: Path) -> None:
    root = _package(tmp_path)
    text = WRAPPER.replace("$(find panda_pkg)/urdf/panda.urdf", "panda.urdf")
    (root / "panda_pkg" / "urdf" / "rel.urdf.xacro").write_text(text)
    urdf = expand_xacro(root, "panda_pkg/urdf/rel.urdf.xacro", {}, XmlLimits())
    assert 'xyz="0.01 -0.02 0.1"' in urdf and "panda_link7" in urdf


def test_include_of_etc_passwd_is_refused_naming_file_and_line(tmp_path: Path) -> None:
    err = _refused(tmp_path, _write(tmp_path, '<xacro:include filename="/etc/passwd"/>'))
    assert err.field == "description"
    assert "pkg/t.urdf.xacro line 2" in err.message and "outside the package" in err.message


def test_include_escaping_with_dotdot_is_refused(tmp_path: Path) -> None:
    (tmp_path / "outside.xacro").write_text(f'<robot {XACRO_NS}><link name="x"/></robot>')
    root = tmp_path / "root"
    root.mkdir()
    err = _refused(root, _write(root, '<xacro:include filename="../../outside.xacro"/>'))
    assert "line 2" in err.message and "outside the package" in err.message


def test_include_through_a_symlink_out_of_the_package_is_refused(tmp_path: Path) -> None:
    (tmp_path / "outside.xacro").write_text(f'<robot {XACRO_NS}><link name="x"/></robot>')
    root = tmp_path / "root"
    description = _write(root, '<xacro:include filename="inside.xacro"/>')
    os.symlink(tmp_path / "outside.xacro", root / "pkg" / "inside.xacro")
    err = _refused(root, description)
    assert "line 2" in err.message and "outside the package" in err.message


def test_find_of_another_package_is_refused(tmp_path: Path) -> None:
    err = _refused(tmp_path, _write(tmp_path, '<xacro:include filename="$(find rospy)/x"/>'))
    assert "$(find rospy)" in err.message and "line 2" in err.message


@pytest.mark.parametrize(
    "expression",
    [
        "''.__class__",
        "python.str.format",
        "python.vars(math)",
        "python.type(1)",
        "(x for x in [1]).gi_frame.f_back",
        "xacro.load_yaml('/etc/passwd')",
    ],
)
def test_expressions_cannot_reach_the_interpreter(tmp_path: Path, expression: str) -> None:
    err = _refused(tmp_path, _write(tmp_path, f'<link name="${{{expression}}}"/>'))
    assert err.field == "description" and "line 2" in err.message


def test_env_is_not_read_and_optenv_gives_its_default(tmp_path: Path) -> None:
    err = _refused(tmp_path, _write(tmp_path, '<link name="$(env HOME)"/>'))
    assert "$(env HOME)" in err.message and os.environ.get("HOME", "/root") not in err.message
    os.environ["DENAVIT_TEST_SECRET"] = "s3cret"
    try:
        body = '<link name="$(optenv DENAVIT_TEST_SECRET unset)"/>'
        urdf = expand_xacro(tmp_path, _write(tmp_path, body), {}, XmlLimits())
    finally:
        del os.environ["DENAVIT_TEST_SECRET"]
    assert 'name="unset"' in urdf


def test_huge_power_is_refused_quickly(tmp_path: Path) -> None:
    start = time.monotonic()
    err = _refused(tmp_path, _write(tmp_path, '<link name="${9**9**9}"/>'), timeout_s=60)
    assert "bits" in err.message and "line 2" in err.message
    assert time.monotonic() - start < 30  # the guard, not the 60 s timeout


def test_huge_string_runs_out_of_memory(tmp_path: Path) -> None:
    err = _refused(tmp_path, _write(tmp_path, "<link name=\"${'a' * 10**10}\"/>"))
    assert "memory" in err.message


def test_endless_macro_recursion_is_refused(tmp_path: Path) -> None:
    body = '<xacro:macro name="m"><xacro:m/></xacro:macro><xacro:m/>'
    err = _refused(tmp_path, _write(tmp_path, body))
    assert "recursion" in err.message


def test_exponential_macro_expansion_is_bounded(tmp_path: Path) -> None:
    macros = "".join(
        f'<xacro:macro name="m{i}"><xacro:m{i - 1}/><xacro:m{i - 1}/></xacro:macro>'
        for i in range(1, 60)
    )
    body = f'<xacro:macro name="m0"><a/></xacro:macro>{macros}<xacro:m59/>'
    description = _write(tmp_path, body)
    with pytest.raises(InvalidInputError) as info:
        expand_xacro(tmp_path, description, {}, XmlLimits(max_elements=500), timeout_s=60)
    assert "nodes" in info.value.message


def test_timeout_kills_the_child(tmp_path: Path) -> None:
    body = '<link name="${python.sum(python.range(10**12))}"/>'
    start = time.monotonic()
    err = _refused(tmp_path, _write(tmp_path, body), timeout_s=1.0)
    # the wall-clock timeout, or (on a starved machine) the CPU rlimit backing it
    assert "longer than 1 s" in err.message or "CPU" in err.message
    assert time.monotonic() - start < 30


def test_syntax_errors_name_file_and_line(tmp_path: Path) -> None:
    err = _refused(tmp_path, _write(tmp_path, '<link name="x">\n  <visual>\n</link>'))
    assert "pkg/t.urdf.xacro" in err.message and "line 4" in err.message
    err = _refused(tmp_path, _write(tmp_path, '<link name="x"/>\n  <link name="${1 +}"/>'))
    assert "pkg/t.urdf.xacro line 3" in err.message and "syntax" in err.message


def test_included_file_errors_name_the_include(tmp_path: Path) -> None:
    description = _write(tmp_path, '<link name="a"/>\n  <xacro:include filename="inc.xacro"/>')
    (tmp_path / "pkg" / "inc.xacro").write_text("<robot>\n<link>\n</robot>")
    err = _refused(tmp_path, description)
    assert "pkg/inc.xacro" in err.message and "line 3" in err.message


@pytest.mark.parametrize("value", [[1, 2], {"a": 1}, None, math.nan])
def test_arg_values_of_unknown_types_are_refused(tmp_path: Path, value: object) -> None:
    description = _write(tmp_path, '<xacro:arg name="a" default="1"/><link name="$(arg a)"/>')
    err = _refused(tmp_path, description, args={"a": value})
    assert err.field == "xacro_args.a"


def test_args_must_be_an_object_of_names(tmp_path: Path) -> None:
    description = _write(tmp_path, '<link name="x"/>')
    assert _refused(tmp_path, description, args=["a"]).field == "xacro_args"
    assert _refused(tmp_path, description, args={"a b": "1"}).field == "xacro_args"


def test_missing_arg_is_a_xacro_args_error(tmp_path: Path) -> None:
    err = _refused(tmp_path, _write(tmp_path, '<link name="$(arg nope)"/>'))
    assert err.field == "xacro_args" and "nope" in err.message


def test_arg_values_are_text_numbers_and_booleans(tmp_path: Path) -> None:
    body = '<xacro:arg name="a" default="x"/><xacro:arg name="b" default="x"/>'
    body += '<link name="$(arg a)_$(arg b)_$(arg c)"/>'
    urdf = expand_xacro(
        tmp_path, _write(tmp_path, body), {"a": 0.5, "b": True, "c": "s"}, XmlLimits()
    )
    assert 'name="0.5_true_s"' in urdf


def test_description_outside_the_package_is_refused(tmp_path: Path) -> None:
    assert _refused(tmp_path, "/etc/passwd").field == "description"
    assert _refused(tmp_path, "../x.xacro").field == "description"


def test_output_limits_apply(tmp_path: Path) -> None:
    links = "".join(f'<link name="l{i}"/>' for i in range(50))
    description = _write(tmp_path, links)
    with pytest.raises(InvalidInputError) as info:
        expand_xacro(tmp_path, description, {}, XmlLimits(max_elements=40))
    assert "DENAVIT_MAX_XML_ELEMENTS" in info.value.message
    with pytest.raises(InvalidInputError) as info:
        expand_xacro(tmp_path, description, {}, XmlLimits(), max_output_chars=500)
    assert "characters" in info.value.message


def _children(pid: int) -> list[int]:
    out = []
    for task in Path(f"/proc/{pid}/task").iterdir():
        try:
            out += [int(c) for c in (task / "children").read_text().split()]
        except OSError:
            pass
    return out


def _cpu_s(pid: int) -> float:
    try:
        fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    except OSError:
        return 0.0
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def _alive(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return False
    return state not in ("Z", "X")


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="PR_SET_PDEATHSIG is Linux's")
def test_the_child_dies_with_its_parent(tmp_path: Path) -> None:
    description = _write(tmp_path, '<link name="${python.sum(python.range(10**14))}"/>')
    script = (
        "from pathlib import Path; from app.robots.documents.xacro import expand_xacro; "
        "from app.kinematics.xmldoc import XmlLimits; "
        f"expand_xacro(Path({str(tmp_path)!r}), {description!r}, {{}}, XmlLimits(), "
        "timeout_s=600)"
    )
    repo = Path(__file__).resolve().parents[3]
    parent = subprocess.Popen([sys.executable, "-c", script], cwd=repo)
    child = None
    try:
        deadline = time.monotonic() + 120
        while child is None and time.monotonic() < deadline and parent.poll() is None:
            kids = _children(parent.pid)
            child = kids[0] if kids else None
            time.sleep(0.05)
        assert child is not None, "the expansion's child process never started"
        while _cpu_s(child) < 1.5 and time.monotonic() < deadline:
            time.sleep(0.05)  # until it is inside the expansion's endless sum
        parent.send_signal(signal.SIGKILL)
        parent.wait()
        deadline = time.monotonic() + 30
        while _alive(child) and time.monotonic() < deadline:
            time.sleep(0.05)
        assert not _alive(child), "the child outlived its parent"
    finally:
        if parent.poll() is None:
            parent.kill()
            parent.wait()
        if child is not None and _alive(child):
            os.kill(child, signal.SIGKILL)
