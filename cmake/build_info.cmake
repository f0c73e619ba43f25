# Writes the build's git commit into a header, at build time (not configure time), so that
# `fastshade report` names the commit it was built from. configure_file leaves the header
# untouched when the commit has not changed, so nothing recompiles then.
#   cmake -DSOURCE_DIR=... -DOUTPUT=.../build_info_generated.h -P build_info.cmake
execute_process(COMMAND git -C "${SOURCE_DIR}" rev-parse HEAD
                OUTPUT_VARIABLE FASTSHADE_GIT_COMMIT OUTPUT_STRIP_TRAILING_WHITESPACE
                RESULT_VARIABLE rev_failed ERROR_QUIET)
if(rev_failed)
  set(FASTSHADE_GIT_COMMIT "unknown")
else()
  # Tracked files edited since that commit: the binary is not exactly that commit.
  execute_process(COMMAND git -C "${SOURCE_DIR}" status --porcelain --untracked-files=no
                  OUTPUT_VARIABLE changes OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(NOT changes STREQUAL "")
    string(APPEND FASTSHADE_GIT_COMMIT "-dirty")
  endif()
endif()
file(WRITE "${OUTPUT}.in" "#define FASTSHADE_GIT_COMMIT \"@FASTSHADE_GIT_COMMIT@\"\n")
configure_file("${OUTPUT}.in" "${OUTPUT}" @ONLY)
