"""The xacro task of the sandbox child: expands one untrusted xacro document.

:func:`run` is called in the bounded child process of :mod:`app.robots.documents.sandbox` (task
``xacro``, started by :func:`app.robots.documents.xacro.expand_xacro`): it expands the document
with the ``xacro`` package and returns the URDF text, or raises
:class:`~app.kinematics.errors.InvalidInputError` naming the file and line.

xacro sees the package at :data:`VIRTUAL_ROOT` (``/package``), never at its place on this
host: ``$(find pkg)``, ``$(dirname)`` and ``xacro.abs_filename()`` give paths under it, so
no path of the server reaches the expanded document or an error message. xacro is confined
by replacing the few functions through which it touches the system:

- files (the description, ``xacro:include``, ``xacro.load_yaml``) are opened only when
  their path is under :data:`VIRTUAL_ROOT` and their real path (symlinks resolved) is a
  regular file inside the package, and each XML file passes
  :func:`app.kinematics.xmldoc.parse_literal_xml` with the upload's limits before xacro
  parses it;
- ``$(find pkg)`` names only the archive's packages, as the parent found them with
  :func:`app.robots.documents.manifests.package_names` (the same names ``package://`` takes), at
  ``/package/<folder>``;
- ``$(env NAME)`` / ``$(optenv NAME default)`` see no environment variable (every one is
  unset: ``env`` is an error, ``optenv`` gives its default); ``$(cwd)`` is refused;
- ``${...}`` and ``$(eval ...)`` go through :mod:`app.robots.documents.xacro_expr`; ``python.type``
  and ``python.vars`` are removed from the symbols;
- macro expansion may clone at most ``4 × max_elements`` nodes (xacro clones about
  10 000 nodes a second).

Every error names the file (relative to the root) and the line of the element being
expanded.
"""

from __future__ import annotations

import os
import posixpath
import re
import stat
import xml.dom.minidom
from dataclasses import dataclass
from pathlib import Path
from typing import Any
from xml.dom import expatbuilder
from xml.parsers import expat

from app.kinematics.errors import InvalidInputError
from app.kinematics.xmldoc import XmlLimits, parse_literal_xml
from app.robots.documents.xacro_expr import GUARDS, ExpressionRefused, compile_expression

#: Where xacro sees the package (every path it computes is under it).
VIRTUAL_ROOT = "/package"
#: Largest file (bytes) the expansion may read (description, include, YAML).
MAX_FILE_BYTES = 8 * 1024 * 1024
#: Nodes macro expansion may clone, per allowed output element.
CLONES_PER_ELEMENT = 4


class Refusal(Exception):  # noqa: N818 - reported to the client as it is
    """An error to report as is, with its field (``description`` or ``xacro_args``)."""

    def __init__(self, message: str, field: str = "description") -> None:
        super().__init__(message)
        self.field = field


class Missing(Refusal):
    """A file that the package does not have (an optional include may skip it)."""


@dataclass
class _State:
    real_root: Path
    limits: XmlLimits
    packages: dict[str, str]
    #: id(node) -> (node, file, line): where each element was written (clones included).
    lines: dict[int, tuple[Any, str, int]]
    clones: int = 0
    current: Any = None


_STATE: _State | None = None


def _state() -> _State:
    assert _STATE is not None
    return _STATE


def _rel(path: str | Path) -> str:
    """``path`` (virtual, or real inside the package) relative to the package's root."""
    text = posixpath.normpath(os.fspath(path))
    for root in (VIRTUAL_ROOT, str(_state().real_root)):
        if text.startswith(root + "/"):
            return text[len(root) + 1 :]
    return text


def real_path(path: str | Path) -> Path | None:
    """The place on this host of a path under :data:`VIRTUAL_ROOT` (``None`` otherwise);
    not resolved: ``..`` and symlinks are the caller's to check."""
    text = os.fspath(path)
    if text == VIRTUAL_ROOT:
        return _state().real_root
    if text.startswith(VIRTUAL_ROOT + "/"):
        return _state().real_root / text[len(VIRTUAL_ROOT) + 1 :]
    return None


def confine(path: str | Path, what: str) -> Path:
    """The real path of the virtual ``path`` if it is a regular file inside the package,
    else refuse."""
    root = _state().real_root
    mapped = real_path(path)
    if mapped is None or "\x00" in os.fspath(path):
        raise Refusal(f"{what} {os.fspath(path)[:200]!r} is outside the package")
    try:
        real = Path(os.path.realpath(mapped))
    except (OSError, ValueError) as exc:
        raise Refusal(f"{what} {_rel(path)!r}: {type(exc).__name__}") from None
    if real != root and root not in real.parents:
        raise Refusal(f"{what} {_rel(path)!r} is outside the package")
    try:
        st = real.stat()
    except OSError:
        raise Missing(f"{what} {_rel(path)!r}: no such file in the package") from None
    if not stat.S_ISREG(st.st_mode):
        raise Refusal(f"{what} {_rel(path)!r} is not a regular file")
    if st.st_size > MAX_FILE_BYTES:
        raise Refusal(f"{what} {_rel(path)!r} is larger than {MAX_FILE_BYTES} bytes")
    return real


def _read_text(path: Path, what: str) -> str:
    with open(path, "rb") as f:
        data = f.read(MAX_FILE_BYTES + 1)
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        raise Refusal(f"{what} {_rel(path)!r} is not UTF-8 text") from None


class _LineBuilder(expatbuilder.ExpatBuilderNS):
    """minidom's builder, recording the file and line of every element."""

    def __init__(self, file: str) -> None:
        super().__init__()
        self._file = file

    def start_element_handler(self, name: str, attributes: Any) -> None:
        super().start_element_handler(name, attributes)
        node = self.curNode
        _state().lines[id(node)] = (node, self._file, self._parser.CurrentLineNumber)


def parse_file(path: str, what: str = "xacro:include of") -> xml.dom.minidom.Document:
    """A DOM of the XML file ``path`` (inside the root), checked with the upload's limits."""
    real = confine(path, what)
    text = _read_text(real, what)
    rel = _rel(real)
    try:
        parse_literal_xml(text, "description", _state().limits)
    except InvalidInputError as exc:
        raise Refusal(f"{rel}: {exc.message}") from None
    try:
        return _LineBuilder(rel).parseString(text.encode("utf-8"))
    except expat.ExpatError as exc:  # pragma: no cover - parse_literal_xml saw it first
        raise Refusal(f"{rel} line {exc.lineno}: not well-formed XML") from None


def _install_hooks(xacro: Any) -> None:
    """Replace the functions through which xacro reaches files, the environment and eval."""
    from xacro import substitution_args as sa

    state = _state()

    def guarded_parse(inp: Any, filename: str | None = None) -> Any:
        if inp is None:
            try:
                return parse_file(xacro.abs_filename_spec(filename))
            except Missing as exc:  # as xacro reports it, so that optional="true" skips it
                xacro.filestack.pop()
                raise xacro.XacroException(exc=FileNotFoundError(str(exc))) from exc
        return original_parse(inp, filename)

    original_parse = xacro.parse
    xacro.parse = guarded_parse

    def get_include_files(filename_spec: str, symbols: Any) -> Any:
        spec = xacro.abs_filename_spec(xacro.eval_text(filename_spec, symbols))
        if re.search(r"[*[?]", spec):
            mapped = real_path(spec)
            if mapped is None or ".." in Path(spec).parts:
                raise Refusal(f"xacro:include of {spec[:200]!r} is outside the package")
            import glob

            real = str(state.real_root)
            found = sorted(glob.glob(str(mapped)))[:1000]
            names = [VIRTUAL_ROOT + f[len(real) :] for f in found if f.startswith(real + "/")]
        else:
            names = [spec]
        for name in names:
            xacro.all_includes.append(name)
            yield name

    xacro.get_include_files = get_include_files

    def load_yaml(filename: str) -> Any:
        import yaml

        for unit in xacro.ConstructUnits:
            yaml.SafeLoader.add_constructor(unit.value.tag, unit.constructor)
        real = confine(xacro.abs_filename_spec(filename), "xacro.load_yaml of")
        return xacro.YamlListWrapper.wrap(yaml.safe_load(_read_text(real, "YAML file")))

    xacro.load_yaml = load_yaml

    def safe_eval(expr: str, globals: Any, locals: Any = None) -> Any:
        code = compile_expression(expr)
        globals.update(__builtins__={}, **GUARDS)
        return eval(code, globals, locals)  # noqa: S307 - checked by compile_expression

    xacro.safe_eval = safe_eval

    def sa_eval(s: str, context: dict[str, Any]) -> str:
        context.setdefault("arg", {})
        code = compile_expression(s)
        names = {k: v for k, v in sa._eval_dict.items() if k not in ("env", "optenv", "find")}
        names.update(__builtins__={}, find=find_package, **GUARDS)

        class Args(dict):  # type: ignore[type-arg]
            def __missing__(self, key: str) -> Any:
                if key in context["arg"]:
                    return sa.convert_value(context["arg"][key], "auto")
                raise NameError(f"name {key!r} is not defined")

        return str(eval(code, names, Args(names)))  # noqa: S307 - checked

    sa._eval = sa_eval

    def find_package(pkg: str) -> str:
        if pkg in state.packages:
            return str(state.packages[pkg])
        known = ", ".join(sorted(state.packages)) or "none"
        raise Refusal(f"$(find {pkg}): not this package (packages in the archive: {known})")

    sa._eval_find = find_package

    def eval_env(name: str) -> str:
        raise Refusal(
            f"$(env {name}): environment variables are not available to uploaded "
            "descriptions (every one is unset; $(optenv) gives its default)"
        )

    sa._eval_env = eval_env
    sa._eval_optenv = lambda name, default="": default

    def eval_extension(s: str) -> Any:
        if s.strip() == "$(cwd)":
            raise Refusal("$(cwd) is not available to uploaded descriptions")
        try:
            return sa.resolve_args(s, context=xacro.substitution_args_context)
        except sa.ArgException as exc:
            raise Refusal(f"$(arg {exc}): not set (give it in xacro_args)", "xacro_args") from None
        except sa.SubstitutionException as exc:
            raise Refusal(str(exc)) from None
        except (Refusal, ExpressionRefused, MemoryError, RecursionError):
            raise
        except Exception as exc:
            raise xacro.XacroException(f"{s}: {type(exc).__name__}: {exc}") from None

    xacro.eval_extension = eval_extension

    original_clone = xml.dom.minidom._clone_node
    max_clones = CLONES_PER_ELEMENT * state.limits.max_elements

    def clone_node(node: Any, deep: bool, owner: Any) -> Any:
        state.clones += 1
        if state.clones > max_clones:
            raise Refusal(
                f"macro expansion made more than {max_clones} nodes "
                f"({CLONES_PER_ELEMENT} × DENAVIT_MAX_XML_ELEMENTS)"
            )
        clone = original_clone(node, deep, owner)
        where = state.lines.get(id(node))
        if where is not None:
            state.lines[id(clone)] = (clone, where[1], where[2])
        return clone

    xml.dom.minidom._clone_node = clone_node

    stack: list[Any] = []
    original_eval_all = xacro.eval_all

    def eval_all(node: Any, macros: Any, symbols: Any) -> None:
        stack.append(node)
        state.current = node
        original_eval_all(node, macros, symbols)
        stack.pop()
        state.current = stack[-1] if stack else None

    xacro.eval_all = eval_all

    def tracked(fn: Any) -> Any:
        def wrapper(node: Any, *args: Any, **kwargs: Any) -> Any:
            state.current = node
            return fn(node, *args, **kwargs)

        return wrapper

    for name in ("check_attrs", "reqd_attrs", "handle_macro_call"):
        setattr(xacro, name, tracked(getattr(xacro, name)))

    symbols = xacro.create_global_symbols()  # with the confined load_yaml
    for table in (symbols, symbols["python"]):
        for unsafe in ("type", "vars"):
            dict.pop(table, unsafe, None)
    xacro._global_symbols = symbols


def _where() -> str:
    state = _state()
    node = state.current
    while node is not None:
        where = state.lines.get(id(node))
        if where is not None:
            return f"{where[1]} line {where[2]}"
        node = getattr(node, "parentNode", None)
    return ""


def _message(exc: BaseException) -> tuple[str, str]:
    """The client's message and field for an exception from the expansion."""
    field = "description"
    chain: list[BaseException] = []
    seen: BaseException | None = exc
    while seen is not None and len(chain) < 50:
        chain.append(seen)
        if isinstance(seen, Refusal):
            field = seen.field
        seen = getattr(seen, "exc", None) or seen.__cause__ or seen.__context__
    if any(isinstance(e, MemoryError) for e in chain):
        text = "the expansion ran out of memory (DENAVIT_XACRO_MEMORY_BYTES)"
    elif any(isinstance(e, RecursionError) for e in chain):
        text = "macros or properties nested too deeply (recursion)"
    else:
        text = str(exc) or type(exc).__name__
        text = re.sub(r"<class '[\w.]+'>: ", "", text)
    if _STATE is not None:
        for root in (str(_STATE.real_root), VIRTUAL_ROOT):
            text = text.replace(f"{root}/", "").replace(root, ".")
    text = " ".join(text.split())[:2000]
    where = _where() if _STATE is not None else ""
    return (f"{where}: {text}" if where else text), field


def expand(
    root: Path,
    description: str,
    args: dict[str, str],
    limits: XmlLimits,
    packages: dict[str, str],
) -> str:
    """Expand ``root / description`` (in this process: call it only in the child).

    ``packages`` maps each name ``$(find <pkg>)`` knows to its folder relative to ``root``.
    xacro sees ``root`` as :data:`VIRTUAL_ROOT`.
    """
    global _STATE
    import xacro

    virtual = {
        name: posixpath.join(VIRTUAL_ROOT, folder).rstrip("/") for name, folder in packages.items()
    }
    _STATE = _State(Path(os.path.realpath(root)), limits, virtual, {})
    _install_hooks(xacro)
    path = posixpath.join(VIRTUAL_ROOT, description)
    xacro.init_stacks(path)
    doc = parse_file(path, "description")
    xacro.process_doc(doc, mappings=dict(args))
    return doc.toprettyxml(indent="  ")


def run(args: dict[str, Any]) -> str:
    """The sandbox task: the URDF text of ``args["description"]`` (a path in the package
    ``args["root"]``) expanded with ``args["args"]``; refusals name the file and line."""
    try:
        urdf = expand(
            Path(args["root"]),
            args["description"],
            args["args"],
            XmlLimits(**args["limits"]),
            args["packages"],
        )
    except BaseException as exc:  # noqa: BLE001 - every failure is the client's document
        message, field = _message(exc)
        raise InvalidInputError(message, field) from None
    if len(urdf) > args["max_output_chars"]:
        raise InvalidInputError(
            f"the expanded document has more than {args['max_output_chars']} characters "
            "(DENAVIT_XACRO_MAX_OUTPUT_CHARS)",
            "description",
        )
    return urdf
