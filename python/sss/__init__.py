"""Translucent surfel clouds for VTK: the classes of the SSS::Translucency module.

They mix freely with ``vtkmodules`` objects (actors, renderers, polydata)."""
from .sssTranslucency import *  # noqa: F401,F403
