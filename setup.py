"""Package discovery; everything else about the package is in pyproject.toml.

Every package below ``geomcad/`` ships, and so does ``constructions/`` as ``geomcad_constructions``
with any sub-package it gains: a folder added later ships without a hand list to update.
"""

from setuptools import find_packages, setup

LIBRARY = find_packages(include=["geomcad", "geomcad.*"])
PROBLEMS = [
    "geomcad_constructions" + name.removeprefix("constructions")
    for name in find_packages(include=["constructions", "constructions.*"])
]

setup(packages=LIBRARY + PROBLEMS)
