# The install layout, and the build tree laid out the same way, so that one run-time rule (brash/paths.hpp) finds
# the data from <prefix>/bin and from <build>/bin alike, with no source or build path compiled in:
#   <prefix>/bin/brash-*                      the tools
#   <prefix>/share/brash/cases/<name>/        case folders (data only)
#   <prefix>/share/brash/hull_meshes/         the JBC model hull STL; data/ the JBC offsets and profile
#   <prefix>/share/brash/study/               the study files
#   <prefix>/share/brash/study_report/templates/   the study document's prose
#   <prefix>/lib/brash/python/                the YADE module, its PyRunner adapter and the scene script
#   <prefix>/share/doc/brash/                 the LIGGGHTS fix pages
# In the build tree, <build>/share/brash/... are symbolic links to the repository's folders (edits show at once;
# packings generated in a case folder land in the repository's case folder, as before) and to generated files.
set(BRASH_DATA_DESTINATION ${CMAKE_INSTALL_DATADIR}/brash)
set(BRASH_BUILD_DATA_DIR ${CMAKE_BINARY_DIR}/share/brash)
# lib/brash/python, not ${CMAKE_INSTALL_LIBDIR}: the run-time rule looks for it at <prefix>/lib/brash/python.
set(BRASH_PYTHON_DESTINATION lib/brash/python)

# brash_stage_data(<path under share/brash> <file or folder>): link it into <build>/share/brash.
function(brash_stage_data relative target)
  set(link ${BRASH_BUILD_DATA_DIR}/${relative})
  get_filename_component(parent ${link} DIRECTORY)
  file(MAKE_DIRECTORY ${parent})
  if(IS_SYMLINK ${link} OR EXISTS ${link})
    file(REMOVE ${link})
  endif()
  file(CREATE_LINK ${target} ${link} SYMBOLIC)
endfunction()

# brash_stage_python_dir(<folder>): <build>/lib/brash/python links to the folder the YADE module is built in.
function(brash_stage_python_dir folder)
  set(link ${CMAKE_BINARY_DIR}/${BRASH_PYTHON_DESTINATION})
  get_filename_component(parent ${link} DIRECTORY)
  file(MAKE_DIRECTORY ${parent})
  if(IS_SYMLINK ${link} OR EXISTS ${link})
    file(REMOVE ${link})
  endif()
  file(CREATE_LINK ${folder} ${link} SYMBOLIC)
endfunction()
