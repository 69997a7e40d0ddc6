"""How the service is served: what runs below the ASGI application, in uvicorn.

- :mod:`app.server.http_protocol`: uvicorn's httptools protocol with request heads bounded
  (431), which ``python -m app`` serves with (:func:`app.__main__.server_options`).
"""
