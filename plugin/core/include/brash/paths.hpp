// Where brash finds its data at run time: the one rule every tool uses (README.md "Install").
// Nothing here knows the source or the build tree. The data folder is, in order:
//   1. $BRASH_DATA_DIR, when set (taken as it is);
//   2. <prefix>/share/brash, where <prefix> is the parent of the running executable's folder (an installed
//      <prefix>/bin/brash-*) or, for programs one or two folders deeper (the build tree's tests), the nearest
//      ancestor that has a share/brash folder. The build tree is laid out like an install: build/share/brash
//      links to the repository's data (cases/, study/, the hull data, the study report template) and the
//      generated JBC hull.
// Tools that run other brash tools start them from executable_dir(); the YADE module is found in
// <prefix>/lib/brash/python (yade_python_dir()).
#pragma once
#include <filesystem>
#include <string>

namespace brash::paths {

// The folder of the running executable (/proc/self/exe).
std::filesystem::path executable_dir();

// The data folder (rule above). When no candidate exists it returns <exe dir>/../share/brash, the installed
// location, so that a later "not found" names where the file was expected. Never throws.
std::filesystem::path data_dir();

// data_dir() / relative, which must exist; throws brash::InputError naming `what`, the path and how to point
// brash at its data (BRASH_DATA_DIR) otherwise.
std::filesystem::path data_file(const std::filesystem::path& relative, const std::string& what);

// The folder of the YADE Python module and scene scripts: $BRASH_YADE_PYDIR, else <prefix>/lib/brash/python.
std::filesystem::path yade_python_dir();

// How data_dir() was found, for messages: "$BRASH_DATA_DIR (/x)" or "/prefix/share/brash".
std::string data_dir_description();

}  // namespace brash::paths
