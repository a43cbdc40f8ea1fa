#pragma once
// A postprocessor header of the fixture tree: the geometry layer may not include it.
