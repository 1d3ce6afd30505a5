# Packaging: a Debian package and a tarball of the installed programs (cpack in the build
# folder; scripts/test-package checks the DEB). What is installed: installer/CMakeLists.txt.
set(CPACK_PACKAGE_NAME "trilho")
set(CPACK_PACKAGE_VENDOR "trilho developers")
set(CPACK_PACKAGE_CONTACT "trilho developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_DESCRIPTION
    "trilho compiles a small G-code dialect and runs it on a robot rail or small XY tables, \
closing the servo loop itself. This package holds the operator screens (trilho), the command \
line (trilho-cli), example programs, machine profiles, translations (pt_BR, es) and a \
faithful simulated rail, so everything runs with no hardware.")
set(CPACK_GENERATOR "TGZ;DEB")
set(CPACK_PACKAGING_INSTALL_PREFIX "/usr")
set(CPACK_DEBIAN_PACKAGE_SECTION "science")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_STRIP_FILES ON)  # the release build keeps debug info; the package does not
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
include(CPack)
