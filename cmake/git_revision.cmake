# Writes OUTPUT, a header defining DDCONTACT_GIT_REVISION as the short git
# revision of SOURCE_DIR (with "-modified" when tracked files differ from
# it), at every build. The file is rewritten only when the revision
# changes, so that only version.cc recompiles, and only then.
execute_process(COMMAND git rev-parse --short HEAD
  WORKING_DIRECTORY ${SOURCE_DIR}
  OUTPUT_VARIABLE revision OUTPUT_STRIP_TRAILING_WHITESPACE
  RESULT_VARIABLE failed ERROR_QUIET)
if(failed OR NOT revision)
  set(revision "unknown")
else()
  execute_process(COMMAND git diff --quiet HEAD --
    WORKING_DIRECTORY ${SOURCE_DIR}
    RESULT_VARIABLE modified ERROR_QUIET)
  if(modified)
    set(revision "${revision}-modified")
  endif()
endif()
set(content "#define DDCONTACT_GIT_REVISION \"${revision}\"\n")
set(old "")
if(EXISTS ${OUTPUT})
  file(READ ${OUTPUT} old)
endif()
if(NOT old STREQUAL content)
  file(WRITE ${OUTPUT} "${content}")
endif()
