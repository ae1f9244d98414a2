# Decides whether the CUDA backend is built. AUTO builds it whenever nvcc is
# found (our machines have it even without a GPU), so CI compiles the CUDA code
# on every run; ON makes a missing toolkit an error; OFF skips it.
set(DEWPOINT_HAVE_CUDA OFF)
string(TOUPPER "${DEWPOINT_CUDA}" _dp_cuda)
if(NOT _dp_cuda MATCHES "^(AUTO|ON|OFF)$")
  message(FATAL_ERROR "DEWPOINT_CUDA must be AUTO, ON or OFF; found '${DEWPOINT_CUDA}'")
endif()

if(NOT _dp_cuda STREQUAL "OFF")
  if(NOT CMAKE_CUDA_COMPILER)
    find_program(_dp_nvcc nvcc HINTS /usr/local/cuda/bin ENV CUDA_PATH PATH_SUFFIXES bin)
    if(_dp_nvcc)
      set(CMAKE_CUDA_COMPILER "${_dp_nvcc}")
    endif()
  endif()
  if(CMAKE_CUDA_COMPILER)
    if(NOT CMAKE_CUDA_ARCHITECTURES)
      # Hopper (H100/H200) machine code plus PTX so newer GPUs JIT it.
      set(CMAKE_CUDA_ARCHITECTURES 90-real 90-virtual)
    endif()
    enable_language(CUDA)
    set(CMAKE_CUDA_STANDARD 17)  # CMake 3.25 knows no C++20 flag for nvcc 13; kernels are C++17
    set(CMAKE_CUDA_STANDARD_REQUIRED ON)
    find_package(CUDAToolkit REQUIRED)
    set(DEWPOINT_HAVE_CUDA ON)
    message(STATUS "dewpoint: CUDA backend ON (nvcc ${CMAKE_CUDA_COMPILER_VERSION}, architectures ${CMAKE_CUDA_ARCHITECTURES})")
  elseif(_dp_cuda STREQUAL "ON")
    message(FATAL_ERROR "DEWPOINT_CUDA=ON but nvcc was not found (looked in PATH, /usr/local/cuda/bin, $CUDA_PATH)")
  else()
    message(STATUS "dewpoint: CUDA backend OFF (no nvcc found)")
  endif()
endif()

if(DEWPOINT_HAVE_CUDA)
  set(DEWPOINT_HAVE_CUDA_INT true)
else()
  set(DEWPOINT_HAVE_CUDA_INT false)
endif()

# CCCL (Thrust, CUB, libcu++) ships with the CUDA toolkit and also compiles
# with the host compiler, which gives the CPU backend the same algorithms.
find_path(DEWPOINT_CCCL_INCLUDE_DIR thrust/sort.h
  HINTS /usr/local/cuda/include/cccl ENV CUDA_PATH
  PATH_SUFFIXES include/cccl)
if(NOT DEWPOINT_CCCL_INCLUDE_DIR)
  message(FATAL_ERROR "dewpoint: CCCL (Thrust/CUB) headers not found; install the CUDA toolkit (expected /usr/local/cuda/include/cccl)")
endif()

# For scripts that read the build folder (pipelines/gpu-bundle.sh): whether
# this build has the CUDA backend, and with which compiler.
set(DEWPOINT_BUILT_CUDA ${DEWPOINT_HAVE_CUDA} CACHE INTERNAL "whether this build has the CUDA backend")
set(DEWPOINT_BUILT_NVCC "${CMAKE_CUDA_COMPILER}" CACHE INTERNAL "the nvcc this build used")
set(DEWPOINT_BUILT_CUDA_ARCHITECTURES "${CMAKE_CUDA_ARCHITECTURES}" CACHE INTERNAL "the CUDA architectures this build compiled for")
