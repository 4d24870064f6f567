# bench(1) and bench's bash completion, written at build time by the freshly built bench from the tables
# its --help prints (bench/lib/options/ManPage.h, BashCompletion.h), so neither can drift from the binary:
#   build/bench.1                    the man page (man -l build/bench.1)
#   build/bench.1.gz                 the same, compressed as Debian's policy wants it installed
#   build/bench-completion.bash      `source` it, or let bash-completion load it once installed
# and installed to share/man/man1/bench.1.gz and share/bash-completion/completions/bench.
#
# Included from CMakeLists.txt; the same file runs each generation as a script
#   cmake -DBENCH=... -DARGS=arg1,arg2 -DOUTPUT=... [-DGZIP=...] -P ManAndCompletion.cmake
# because a build rule cannot redirect a program's stdout portably (ARGS comma-separated: a ';' does not
# survive the build tool's command line).
if(CMAKE_SCRIPT_MODE_FILE)
  string(REPLACE "," ";" ARGS "${ARGS}")
  execute_process(COMMAND "${BENCH}" ${ARGS} OUTPUT_FILE "${OUTPUT}" RESULT_VARIABLE failed)
  if(failed)
    message(FATAL_ERROR "${BENCH} ${ARGS} failed: ${failed}")
  endif()
  if(GZIP)
    # -n: no name or time stamp inside, so the same page compresses to the same bytes (reproducible).
    execute_process(COMMAND "${GZIP}" -9 -n -f -k "${OUTPUT}" RESULT_VARIABLE failed)
    if(failed)
      message(FATAL_ERROR "${GZIP} ${OUTPUT} failed: ${failed}")
    endif()
  endif()
  return()
endif()

find_program(SB_GZIP gzip)
# The built-in scenes are listed from their files: a new one regenerates both outputs.
file(GLOB SB_SCENE_FILES CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/scenes/data/*.json)
set(SB_MAN_PAGE ${CMAKE_BINARY_DIR}/bench.1)
set(SB_COMPLETION ${CMAKE_BINARY_DIR}/bench-completion.bash)
set(SB_MAN_OUTPUTS ${SB_MAN_PAGE})
if(SB_GZIP)
  list(APPEND SB_MAN_OUTPUTS ${SB_MAN_PAGE}.gz)
endif()
add_custom_command(OUTPUT ${SB_MAN_OUTPUTS}
  COMMAND ${CMAKE_COMMAND} -DBENCH=$<TARGET_FILE:bench> -DARGS=--man -DOUTPUT=${SB_MAN_PAGE}
          -DGZIP=${SB_GZIP} -P ${CMAKE_CURRENT_LIST_DIR}/ManAndCompletion.cmake
  DEPENDS bench ${SB_SCENE_FILES} ${CMAKE_CURRENT_LIST_DIR}/ManAndCompletion.cmake
  COMMENT "Writing the man page bench.1 with bench --man" VERBATIM)
add_custom_command(OUTPUT ${SB_COMPLETION}
  COMMAND ${CMAKE_COMMAND} -DBENCH=$<TARGET_FILE:bench> -DARGS=--completion,bash -DOUTPUT=${SB_COMPLETION}
          -P ${CMAKE_CURRENT_LIST_DIR}/ManAndCompletion.cmake
  DEPENDS bench ${SB_SCENE_FILES} ${CMAKE_CURRENT_LIST_DIR}/ManAndCompletion.cmake
  COMMENT "Writing the bash completion with bench --completion bash" VERBATIM)
add_custom_target(sb_man_and_completion ALL DEPENDS ${SB_MAN_OUTPUTS} ${SB_COMPLETION})

if(SB_GZIP)
  install(FILES ${SB_MAN_PAGE}.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
else()
  install(FILES ${SB_MAN_PAGE} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
endif()
install(FILES ${SB_COMPLETION} DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME bench)
