"""geomcad's problems, one module per problem id (installed as ``geomcad_constructions``).

Each module defines ``PROBLEM``; pyproject.toml registers it under the ``geomcad.constructions``
entry-point group, which is how the CLI and :func:`geomcad.solve` find it.
"""
