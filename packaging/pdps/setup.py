"""The pdps meta-distribution: no code of its own; it requires pdps-core and every distribution under
plugins/ (the standard packs and the libraries they share), each pinned to the version in this tree,
so a pack added to plugins/ joins it with no change here. Built by `make dist`."""

import pathlib
import tomllib

from setuptools import setup

TREE = pathlib.Path(__file__).resolve().parents[2]


def pinned(pyproject):
    project = tomllib.loads(pyproject.read_text())["project"]
    return f"{project['name']}=={project['version']}"


setup(install_requires=[pinned(TREE / "pyproject.toml")]
      + [pinned(path) for path in sorted(TREE.glob("plugins/*/pyproject.toml"))])
