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
pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)

if(SCULPT_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(SCULPT_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED)
endif()
