"""The discretization: meshes, element shapes and the influence matrices of a model.

``elements.py`` (meshes, element shapes and the stores a caller owns),
``influence.py`` (collocation of ring and strip loads) and ``operators.py`` (the
operators every solver asks for, with their compiled part ``operators_fused``).
Nothing is re-exported: ``contactlib.discretization.X`` is the way to use them.
"""
