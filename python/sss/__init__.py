"""Translucent surfel clouds for VTK: the classes of the SSS::Translucency module (the surfel
mapper, the subsurface pass, the material) and of SSS::Headless (render windows that need no
display).

They mix freely with ``vtkmodules`` objects (actors, renderers, polydata)."""
from .sssTranslucency import *  # noqa: F401,F403
from .sssHeadless import *  # noqa: F401,F403
