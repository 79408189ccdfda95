# Writes the software version source (cmake/software_version.cpp.in) at every build, not only at
# configure time: the version is what keeps a cached reduced model valid, so it must follow every
# commit and every uncommitted change the build compiles. configure_file() rewrites the output
# only when its text changes, so an unchanged version recompiles nothing.
#
#   cmake -DTVD_PROJECT_VERSION=0.3.0 -DTVD_SOURCE_DIR=... -DTVD_TEMPLATE=... -DTVD_OUTPUT=...
#         [-DGIT_EXECUTABLE=...] -P software_version.cmake
#
# The version is the package version plus, in a git checkout, the commit ("-dirty" when the work
# tree differs from it); without git (a source archive) the package version alone.
set(TVD_SOFTWARE_VERSION "${TVD_PROJECT_VERSION}")
if(GIT_EXECUTABLE AND EXISTS "${TVD_SOURCE_DIR}/.git")
  execute_process(
    COMMAND "${GIT_EXECUTABLE}" describe --always --dirty --abbrev=12 --match=no-tags-wanted
    WORKING_DIRECTORY "${TVD_SOURCE_DIR}"
    OUTPUT_VARIABLE TVD_GIT_DESCRIPTION OUTPUT_STRIP_TRAILING_WHITESPACE
    RESULT_VARIABLE TVD_GIT_RESULT ERROR_QUIET)
  if(TVD_GIT_RESULT EQUAL 0 AND TVD_GIT_DESCRIPTION)
    set(TVD_SOFTWARE_VERSION "${TVD_PROJECT_VERSION}+${TVD_GIT_DESCRIPTION}")
  else()
    # A checkout whose commit cannot be read (git refusing a directory it does not own, say)
    # would let caches outlive commits: say so.
    message(WARNING "software version: git describe failed in ${TVD_SOURCE_DIR}; the version is "
                    "${TVD_PROJECT_VERSION} without the commit, so reduced-model caches are not "
                    "invalidated by new commits (clear them when the model code changes)")
  endif()
endif()
configure_file("${TVD_TEMPLATE}" "${TVD_OUTPUT}" @ONLY)
