"""The checks of scripts/check_docs.py, one module per kind: paths, flags, citations, units."""
