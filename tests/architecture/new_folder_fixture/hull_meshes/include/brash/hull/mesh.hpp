#pragma once
// A geometry header of the fixture tree.
