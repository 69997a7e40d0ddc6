# syntax=docker/dockerfile:1
# Denavit: kinematics of robot arms over HTTP.
#   make image            (docker build -t denavit . where a Docker engine runs, else podman)
#   docker run -p 8000:8000 -v denavit-data:/data denavit
# Settings are DENAVIT_* environment variables (docs/deployment.md). CI builds and runs
# this file for real with podman (.ci/container-check.sh, `make container-check`).

# ---- build: the locked dependencies and the project in a trimmed virtualenv ------------
FROM python:3.11-slim-bookworm AS build
ENV PIP_DISABLE_PIP_VERSION_CHECK=1 \
    PIP_NO_CACHE_DIR=1 \
    PYTHONDONTWRITEBYTECODE=1
# libgomp1: the OpenMP runtime that Pinocchio and Numba load; binutils: strip. Debian
# packages are not version-pinned: bookworm's point releases replace them (security
# fixes, same ABI) and drop the old versions from the mirrors.
# hadolint ignore=DL3008
RUN apt-get update \
    && apt-get install -y --no-install-recommends libgomp1 binutils \
    && rm -rf /var/lib/apt/lists/*
RUN python -m venv /opt/venv
# Exactly the hash-checked packages of the runtime lock (make lock), resolved nothing.
COPY requirements.lock /src/
RUN /opt/venv/bin/pip install --no-deps --require-hashes -r /src/requirements.lock
COPY pyproject.toml README.md /src/
COPY app /src/app
COPY dh2urdf /src/dh2urdf
COPY robots /src/robots
COPY deploy/slim_venv.py /src/deploy/
# The project (built with the locked setuptools), then the trim (deploy/slim_venv.py
# says what goes and why), then no source tree: what follows imports the installed copy.
RUN /opt/venv/bin/pip install --no-deps --no-build-isolation /src \
    && /opt/venv/bin/python /src/deploy/slim_venv.py /opt/venv /src/robots/example_robot_data.yaml \
    && rm -rf /src
# Numba compiles the IK kernels into NUMBA_CACHE_DIR, keyed by the path of the module
# (the site-packages copy the service imports) and by the CPU: "generic" x86-64 code, so
# the cache is valid on any host the image runs on, not only on the one that built it.
ENV NUMBA_CACHE_DIR=/opt/numba-cache \
    NUMBA_CPU_NAME=generic
# The second run, a new process, must load every kernel from that cache.
WORKDIR /
RUN /opt/venv/bin/python -m app warm-up \
    && /opt/venv/bin/python -m app warm-up --require-cache

# ---- runtime: the virtualenv and the kernel cache, as an unprivileged user -------------
FROM python:3.11-slim-bookworm
ENV PATH=/opt/venv/bin:$PATH \
    PYTHONUNBUFFERED=1 \
    PYTHONDONTWRITEBYTECODE=1 \
    DENAVIT_HOST=0.0.0.0 \
    DENAVIT_PORT=8000 \
    DENAVIT_WORKERS=2 \
    DENAVIT_DATA_DIR=/data \
    NUMBA_CACHE_DIR=/opt/numba-cache \
    NUMBA_CPU_NAME=generic
# libgomp1 as in the build stage; user and group denavit, both 10001.
# hadolint ignore=DL3008
RUN apt-get update \
    && apt-get install -y --no-install-recommends libgomp1 \
    && rm -rf /var/lib/apt/lists/* \
    && groupadd --system --gid 10001 denavit \
    && useradd --system --no-log-init --uid 10001 --gid denavit --create-home denavit \
    && mkdir -p /data \
    && chown denavit:denavit /data
COPY --from=build /opt/venv /opt/venv
COPY --from=build --chown=10001:10001 /opt/numba-cache /opt/numba-cache
USER 10001:10001
WORKDIR /home/denavit
VOLUME ["/data"]
EXPOSE 8000
HEALTHCHECK --interval=30s --timeout=5s --start-period=30s --retries=3 \
    CMD ["python", "-m", "app", "healthcheck"]
# The same entry as `make run`: uvicorn with DENAVIT_WORKERS workers, graceful on SIGTERM.
CMD ["python", "-m", "app"]
