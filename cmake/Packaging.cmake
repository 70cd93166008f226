# The Debian package: `cpack -G DEB` in the build folder (scripts/package) packs what
# `cmake --install` lays out under /usr. dpkg-shlibdeps finds the libraries the binary links;
# the rest are what it loads at run time.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME vectorfluid)
set(CPACK_PACKAGE_CONTACT "Vector Fluid maintainers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "design tool: ink as vector contours carried by a 2D fluid")
# Lines of the long description stay under 80 columns, as Debian asks.
set(CPACK_PACKAGE_DESCRIPTION "Ink regions are closed vector contours carried by a viscous 2D fluid:
drop ink, drag strokes through it, and export every frame as exact SVG, PDF
or EPS.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Qt's platform plugins (the window needs one) and the text tool's first typeface.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "qt6-qpa-plugins, fonts-dejavu-core")
# The OpenCL backend needs a driver; without one, renders fall back to the reference backend. Video
# export (.mp4, .gif) runs the ffmpeg program; without it that export says so.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "pocl-opencl-icd | opencl-icd, ffmpeg")
include(CPack)
