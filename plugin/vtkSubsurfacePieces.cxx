#include "vtkSubsurfacePieces.h"
