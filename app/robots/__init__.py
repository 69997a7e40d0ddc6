"""Which robots exist and how a model is made from one: every robot id (``registry``), the
built-in ones (``catalog``) and the checks of a client's documents (``documents/``)."""
