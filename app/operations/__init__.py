"""Running the service: configuration (``settings``), JSON logs (``logs``), Prometheus
metrics (``metrics``: the families and the recording API; ``metrics_files``: this process's
values in prometheus_client's multiprocess files; ``metrics_workers``: the instance
directory, the workers alive and dead, their process metrics)."""
