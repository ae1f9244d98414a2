# Every dependency is a Debian package; pipelines/install-deps.sh installs them.
# A missing one stops the configuration here, naming the package to install.
function(dewpoint_require package debian_package)
  find_package(${package} ${ARGN} QUIET)
  if(NOT ${package}_FOUND)
    message(FATAL_ERROR "dewpoint: missing dependency ${package}; install the Debian package '${debian_package}' (or run pipelines/install-deps.sh)")
  endif()
endfunction()

find_package(OpenMP QUIET)
if(NOT OpenMP_CXX_FOUND)
  message(FATAL_ERROR "dewpoint: the C++ compiler has no OpenMP support (needed by the CPU backend); install g++ from Debian")
endif()

# GoogleTest. A machine without Debian packages (the lent GPU machines) builds
# it from its source folder, carried along: -DDEWPOINT_GTEST_SOURCE=DIR
# (Debian's googletest package installs one at /usr/src/googletest).
set(DEWPOINT_GTEST_SOURCE "" CACHE PATH "GoogleTest source folder, used where no installed GTest is found")
find_package(GTest QUIET)
if(NOT GTest_FOUND)
  if(DEWPOINT_GTEST_SOURCE AND EXISTS "${DEWPOINT_GTEST_SOURCE}/CMakeLists.txt")
    set(INSTALL_GTEST OFF CACHE BOOL "" FORCE)
    set(BUILD_GMOCK OFF CACHE BOOL "" FORCE)
    add_subdirectory(${DEWPOINT_GTEST_SOURCE} ${CMAKE_BINARY_DIR}/googletest EXCLUDE_FROM_ALL)
    if(NOT TARGET GTest::gtest)  # googletest >= 1.11 defines these itself
      add_library(GTest::gtest ALIAS gtest)
      add_library(GTest::gtest_main ALIAS gtest_main)
    endif()
  else()
    message(FATAL_ERROR "dewpoint: missing dependency GTest; install the Debian package 'libgtest-dev' (or pass -DDEWPOINT_GTEST_SOURCE=<googletest source folder>)")
  endif()
endif()

if(NOT DEWPOINT_CORE_ONLY)
  dewpoint_require(Eigen3 libeigen3-dev NO_MODULE)
  dewpoint_require(nlohmann_json nlohmann-json3-dev)
endif()

if(NOT DEWPOINT_CORE_ONLY)
  dewpoint_require(CLI11 libcli11-dev)
  dewpoint_require(TBB libtbb-dev)
  dewpoint_require(assimp libassimp-dev)
  dewpoint_require(embree libembree-dev 3)
  dewpoint_require(OpenImageIO libopenimageio-dev)
  dewpoint_require(OpenEXR libopenexr-dev)
  # Debian's OpenImageIO target lists /usr/include/opencv4 among its include
  # directories without depending on OpenCV, and CMake rejects a target naming
  # a missing directory. Only existing ones are kept.
  foreach(_dp_property INTERFACE_INCLUDE_DIRECTORIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES)
    get_target_property(_dp_dirs OpenImageIO::OpenImageIO ${_dp_property})
    if(_dp_dirs)
      set(_dp_existing)
      foreach(_dp_dir IN LISTS _dp_dirs)
        if(EXISTS "${_dp_dir}")
          list(APPEND _dp_existing "${_dp_dir}")
        endif()
      endforeach()
      set_target_properties(OpenImageIO::OpenImageIO PROPERTIES ${_dp_property} "${_dp_existing}")
    endif()
  endforeach()
  dewpoint_require(CGAL libcgal-dev)
  # stb_image and stb_image_resize (max-mass images in the simulator); Debian
  # builds them into one small library without dependencies.
  find_package(PkgConfig QUIET)
  if(PkgConfig_FOUND)
    pkg_check_modules(STB QUIET IMPORTED_TARGET stb)
  endif()
  if(NOT TARGET PkgConfig::STB)
    message(FATAL_ERROR "dewpoint: missing dependency stb; install the Debian package 'libstb-dev' (or run pipelines/install-deps.sh)")
  endif()
  dewpoint_require(benchmark libbenchmark-dev)
  list(APPEND CMAKE_MODULE_PATH /usr/lib/x86_64-linux-gnu/cmake/OpenVDB)
  dewpoint_require(OpenVDB libopenvdb-dev)
  dewpoint_require(ZLIB zlib1g-dev)  # CRC-32 of simulation checkpoints
  find_program(DEWPOINT_OIIOTOOL oiiotool)
  if(NOT DEWPOINT_OIIOTOOL)
    message(FATAL_ERROR "dewpoint: missing oiiotool; install the Debian package 'openimageio-tools'")
  endif()
endif()
