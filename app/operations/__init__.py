"""Running the service: configuration (``settings``), JSON logs (``logs``), Prometheus
metrics (``metrics``)."""
