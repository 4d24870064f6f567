# The Debian package of `cpack -G DEB` (run in the build folder), included by CMakeLists.txt after its
# install rules. What makes it lintian-clean (tests/PackageCliTest.cpp runs lintian on it):
# - stripped binaries (a Release build carries no debug information, so there is no -dbgsym package
#   to split off);
# - /usr/share/doc/shadowbench/copyright in the machine-readable format (cmake/debian/copyright) and a
#   Debian-format changelog.gz for this version, written here from CITATION.cff's release date and
#   pointing at CHANGELOG.md;
# - a maintainer with an address that is not on localhost; the project has no mailing list, so it is
#   the address its commits are made with;
# - Depends from dpkg-shlibdeps plus python3 (tools/*.py have a python3 #! line) and the GL dispatch
#   libraries libepoxy loads; the plot and report
#   libraries and the Mesa drivers as Recommends (a real GPU's driver replaces Mesa; `bench figures`
#   and `bench report` say what to install when matplotlib or pandas is missing);
# - manual pages compressed with gzip -9n, whoever installs them (cmake/debian/GzipManPages.cmake).

set(SB_MAINTAINER "The shadowbench developers <dev@shadowbench.invalid>")

# The release date of CITATION.cff dates the changelog entry, so the package of one version is the same
# whenever it is built.
file(STRINGS ${CMAKE_SOURCE_DIR}/CITATION.cff SB_RELEASED REGEX "^date-released: ")
string(REGEX REPLACE "^date-released: *" "" SB_RELEASED "${SB_RELEASED}")
execute_process(COMMAND date -u -R -d "${SB_RELEASED}" OUTPUT_VARIABLE SB_RELEASED_RFC2822
                OUTPUT_STRIP_TRAILING_WHITESPACE COMMAND_ERROR_IS_FATAL ANY)
set(SB_PACKAGING_DIR ${CMAKE_BINARY_DIR}/packaging)
file(WRITE ${SB_PACKAGING_DIR}/changelog
     "shadowbench (${PROJECT_VERSION}) unstable; urgency=medium\n\n"
     "  * Release ${PROJECT_VERSION}. The changes are listed in\n"
     "    /usr/share/doc/shadowbench/CHANGELOG.md.\n\n"
     " -- ${SB_MAINTAINER}  ${SB_RELEASED_RFC2822}\n")
# -n: no name or time stamp in the gzip header, so the compressed bytes depend on the text alone.
execute_process(COMMAND gzip -9nf ${SB_PACKAGING_DIR}/changelog COMMAND_ERROR_IS_FATAL ANY)
# The manual pages of the two comparison programs (bench's own is generated with its help text).
install(FILES cmake/debian/handloop.1 cmake/debian/handshadow.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
install(FILES ${SB_PACKAGING_DIR}/changelog.gz cmake/debian/copyright DESTINATION ${CMAKE_INSTALL_DOCDIR})

set(CPACK_PACKAGE_NAME shadowbench)
set(CPACK_PACKAGE_VENDOR "The shadowbench developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "benchmark and analysis suite for real-time shadow techniques")
# The long description: lines of at most 80 characters (lintian), CPack indents each by one space.
set(CPACK_PACKAGE_DESCRIPTION
    "shadowbench runs interchangeable real-time shadow techniques (shadow maps,
stencil shadow volumes, occluder textures, shadow proxies, planar, projective
and blob shadows) on the same scenes under OpenGL and Vulkan and measures
them: CPU submit time, wall time, and GPU time per pass where the GPU timer
is shown to measure the frame. It judges each technique's visibility against
an exact ray-traced reference (Intel Embree), sweeps configurations,
classifies bottlenecks, gates performance regressions and reproduces the
figures of its source documents. It runs headless on Mesa's software
renderers (llvmpipe, lavapipe) as well as on real GPUs.")
set(CPACK_PACKAGE_CONTACT "${SB_MAINTAINER}")
set(CPACK_RESOURCE_FILE_LICENSE ${CMAKE_SOURCE_DIR}/LICENSE)
set(CPACK_GENERATOR DEB)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# libepoxy opens the GL and EGL dispatch libraries at run time, so dpkg-shlibdeps does not see them.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3, libegl1, libgl1")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS
    "python3-matplotlib, python3-pandas, libegl-mesa0, libgl1-mesa-dri, mesa-vulkan-drivers")
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
# Directories in the package belong to root and are 0755, whatever the umask of the build.
set(CPACK_INSTALL_DEFAULT_DIRECTORY_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ
                                                GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
set(CPACK_PRE_BUILD_SCRIPTS ${CMAKE_SOURCE_DIR}/cmake/debian/GzipManPages.cmake)
include(CPack)
