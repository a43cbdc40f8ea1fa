// A geometry source including its own header: allowed.
#include "brash/hull/mesh.hpp"
