// A component the layer check does not know yet: its folder must be placed in a layer first.
#include "brash/hull/mesh.hpp"
