"""The ASGI stack around the routes, outermost first: observability (request ids, logs,
metrics), guard (an unexpected exception is a 500 problem), body limit (413 before
parsing), methods (HEAD, 405 with ``Allow``); and the OpenAPI document's shared parts."""
