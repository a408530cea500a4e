# SPDX-License-Identifier: Apache-2.0
# Debian packages (`cpack` in the build directory): sculpt (the programs, their man pages,
# completions, desktop files and data, the Python module) and sculpt-dev (the libraries, headers and CMake package),
# for /usr. The programs' library dependencies are read from the binaries by dpkg-shlibdeps, so
# `apt install ./sculpt_*.deb` on a fresh Debian 12 brings exactly what they need.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME sculpt)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "sculpt developers")
set(CPACK_PACKAGE_CONTACT "sculpt developers <sculpt@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "volumetric clay sculpting on sparse signed-distance grids")
set(CPACK_PACKAGE_DESCRIPTION
    "Sculpt virtual clay kept as an OpenVDB narrow-band level set: brushes, masks, cuts, pieces,
morphs between shapes, and CT/MRI scans turned into printable models. sculpt-ui is the window,
sculpt the command line for every edit in batch jobs.")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL Runtime Development)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # sculpt_0.1.0_amd64.deb
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "https://github.com/volumetric-sculpt/sculpt")
set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME sculpt)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SHLIBDEPS ON)
# The window draws with OpenGL: Mesa's drivers where no other is installed.
set(CPACK_DEBIAN_RUNTIME_PACKAGE_RECOMMENDS "libgl1-mesa-dri, python3-numpy")
# The Python module is built for the system's python3 (its ABI: one minor version).
set(CPACK_DEBIAN_RUNTIME_PACKAGE_DEPENDS
    "python3 (>= ${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}~), python3 (<< ${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}.99)")
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_NAME sculpt-dev)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_SECTION libdevel)
# The static libraries' dependencies are the -dev packages find_package(sculpt) looks for.
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_DEPENDS
    "sculpt (= ${PROJECT_VERSION}), libopenvdb-dev, libvtk9-dev, libopenexr-dev, libtbb-dev, libgdcm-dev, zlib1g-dev, nlohmann-json3-dev, libboost-iostreams-dev")
include(CPack)
