# syntax=docker/dockerfile:1
# Denavit: kinematics of robot arms over HTTP.
#   docker build -t denavit .
#   docker run -p 8000:8000 -v denavit-data:/data denavit
# Settings are DENAVIT_* environment variables (docs/deployment.md).

# ---- build: install the project and its pinned dependencies into a virtualenv ----------
FROM python:3.11-slim-bookworm AS build
ENV PIP_DISABLE_PIP_VERSION_CHECK=1 \
    PYTHONDONTWRITEBYTECODE=1
WORKDIR /src
RUN python -m venv /opt/venv
COPY pyproject.toml README.md ./
COPY app ./app
COPY dh2urdf ./dh2urdf
COPY robots ./robots
# The runtime dependencies are the == pins of pyproject.toml's [project] dependencies.
# The IK kernels are compiled here (Numba) into a cache the runtime user may refresh.
ENV NUMBA_CACHE_DIR=/opt/numba-cache
RUN /opt/venv/bin/pip install --no-cache-dir . \
    && /opt/venv/bin/python -c "import app.main, pinocchio, coal" \
    && /opt/venv/bin/python -c "from app.kinematics import ik; ik.warm_up()"

# ---- runtime: the virtualenv only, as an unprivileged user --------------------------
FROM python:3.11-slim-bookworm
ENV PATH=/opt/venv/bin:$PATH \
    PYTHONUNBUFFERED=1 \
    PYTHONDONTWRITEBYTECODE=1 \
    DENAVIT_HOST=0.0.0.0 \
    DENAVIT_PORT=8000 \
    DENAVIT_WORKERS=2 \
    DENAVIT_DATA_DIR=/data \
    NUMBA_CACHE_DIR=/opt/numba-cache
RUN useradd --system --no-log-init --uid 10001 --user-group --create-home denavit \
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
