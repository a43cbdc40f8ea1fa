// Fixture for check_layers.sh: the geometry layer including the postprocessor (an arrow pointing up).
#include <brash/hull/mesh.hpp>
#include <brash/post/report.hpp>
