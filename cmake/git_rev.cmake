# Writes OUT (a header defining SIMHUMAN_GIT_REV) from `git describe` of SRC, at build time, so
# that `simhuman --version` and result files name the revision that was built, with "-dirty"
# when the work tree had changes. The file is rewritten only when the revision changes.
execute_process(COMMAND git describe --always --dirty --abbrev=12 --exclude=*
                WORKING_DIRECTORY ${SRC} OUTPUT_VARIABLE rev OUTPUT_STRIP_TRAILING_WHITESPACE
                ERROR_QUIET RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR NOT rev)
  set(rev "unknown")
endif()
file(WRITE ${OUT}.tmp "#pragma once\n#define SIMHUMAN_GIT_REV \"${rev}\"\n")
file(COPY_FILE ${OUT}.tmp ${OUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUT}.tmp)
