# CPack runs this after installing into its staging folder and before it builds the package
# (CPACK_PRE_BUILD_SCRIPTS, cmake/Packaging.cmake): every manual page installed uncompressed under
# share/man is compressed with gzip -9n, as Debian policy asks, so the rule that installs a page need
# not know whether it is packaged. A plain `cmake --install` leaves the pages as they are.
file(GLOB_RECURSE pages "${CPACK_TEMPORARY_DIRECTORY}/*/share/man/*")
foreach(page ${pages})
  if(NOT page MATCHES "\\.gz$")
    execute_process(COMMAND gzip -9nf "${page}" COMMAND_ERROR_IS_FATAL ANY)
  endif()
endforeach()
