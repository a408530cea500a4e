# SPDX-License-Identifier: Apache-2.0
# Finds every third-party package. The order matters on Debian 12:
# VTK must come before anything that loads OpenVDB's FindTBB.cmake, otherwise
# CMake stops with "Some (but not all) targets in this export set were already defined".
find_package(VTK 9 REQUIRED COMPONENTS
  CommonCore CommonDataModel FiltersCore FiltersSources IOGeometry IOImage IOPLY ImagingCore ImagingGeneral
  RenderingCore RenderingOpenGL2 RenderingUI)

list(APPEND CMAKE_MODULE_PATH "/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/OpenVDB")  # Debian multiarch
# Debian's FindOpenVDB.cmake asks for Boost iostreams (libboost-iostreams-dev).
find_package(OpenVDB REQUIRED)
find_package(Imath CONFIG REQUIRED)
find_package(OpenEXR CONFIG REQUIRED)
find_package(TBB REQUIRED)
# DICOM: GDCM decodes every transfer syntax archives use (JPEG lossless, JPEG-LS, JPEG 2000,
# RLE) and multi-frame files; only its core libraries, not its VTK classes.
set(GDCM_SKIP_USE_VTK ON)
find_package(GDCM REQUIRED)
find_package(ZLIB REQUIRED)  # reading a .nii.gz header and length before VTK does
find_package(CLI11 CONFIG REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
# The window: GLFW, GLM, and Debian's static Dear ImGui (it holds the GLFW and OpenGL3 backends).
find_package(glfw3 3.3 REQUIRED)
find_package(glm REQUIRED)
find_package(OpenGL REQUIRED)
find_package(PkgConfig REQUIRED)
# The Python module: pybind11 (pybind11-dev) for the system's python3 (python3-dev).
set(PYBIND11_FINDPYTHON ON)
if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3)  # Debian's, which the package installs the module for
endif()
find_package(Python3 COMPONENTS Interpreter Development.Module REQUIRED)
find_package(pybind11 CONFIG REQUIRED)
pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)

if(SCULPT_BUILD_TESTS)
  find_package(GTest REQUIRED)
  # lib3mf (the 3MF Consortium's library): the independent reader the 3MF writer is tested against.
  # Found by hand: its lib3MF.pc asks to link libzip, which only its shared library needs.
  find_library(LIB3MF_LIBRARY 3MF REQUIRED)
  find_path(LIB3MF_INCLUDE_DIR Model/COM/NMR_DLLInterfaces.h PATH_SUFFIXES lib3mf REQUIRED)
  add_library(lib3mf::lib3mf UNKNOWN IMPORTED)
  set_target_properties(lib3mf::lib3mf PROPERTIES IMPORTED_LOCATION "${LIB3MF_LIBRARY}"
                                                  INTERFACE_INCLUDE_DIRECTORIES "${LIB3MF_INCLUDE_DIR}")
endif()
if(SCULPT_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED)
endif()
