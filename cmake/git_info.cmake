# Writes OUTPUT with the current git commit (and whether the tree was dirty),
# touching it only when the content changes so that nothing rebuilds needlessly.
execute_process(COMMAND git rev-parse HEAD WORKING_DIRECTORY ${SOURCE_DIR}
                OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  set(commit "unknown")
endif()
execute_process(COMMAND git status --porcelain --untracked-files=no WORKING_DIRECTORY ${SOURCE_DIR}
                OUTPUT_VARIABLE dirty OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(dirty)
  set(dirty_flag "true")
else()
  set(dirty_flag "false")
endif()
set(content "#pragma once\n#define GEOMINT_GIT_COMMIT \"${commit}\"\n#define GEOMINT_GIT_DIRTY ${dirty_flag}\n")
if(EXISTS ${OUTPUT})
  file(READ ${OUTPUT} old)
endif()
if(NOT "${old}" STREQUAL "${content}")
  file(WRITE ${OUTPUT} "${content}")
endif()
