# Run at build time (cmake -P), not at configure time: writes OUT, the source commit recorded in every
# result's provenance and in the checkpoint's build identity, when it differs from what OUT holds.
# A tree whose tracked files differ from the commit is "<commit>-modified": its results do not claim a
# commit they were not built from.
#   cmake -DSOURCE_DIR=<checkout> -DOUT=<file.cpp> -P git_commit.cmake
execute_process(COMMAND git rev-parse --short=12 HEAD WORKING_DIRECTORY "${SOURCE_DIR}"
                OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR NOT commit)
  set(commit unknown)
else()
  execute_process(COMMAND git diff --quiet HEAD -- WORKING_DIRECTORY "${SOURCE_DIR}" RESULT_VARIABLE changed
                  OUTPUT_QUIET ERROR_QUIET)
  if(changed EQUAL 1)
    string(APPEND commit "-modified")
  endif()
endif()
set(text "// Written at build time by cmake/git_commit.cmake.\n#include \"git_commit.hpp\"\n\nnamespace hm::cases {\nconst char* const kGitCommit = \"${commit}\";\n}\n")
set(old "")
if(EXISTS "${OUT}")
  file(READ "${OUT}" old)
endif()
if(NOT old STREQUAL text)
  file(WRITE "${OUT}" "${text}")
endif()
