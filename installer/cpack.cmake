# Packaging: a Debian package and a tarball of the installed programs.
set(CPACK_PACKAGE_NAME "trilho")
set(CPACK_PACKAGE_VENDOR "trilho developers")
set(CPACK_PACKAGE_CONTACT "trilho developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_GENERATOR "TGZ;DEB")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
include(CPack)
