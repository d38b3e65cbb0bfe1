# The student presets' toolchain file (CMakePresets.json): vcpkg's when the environment names a
# vcpkg (VCPKG_ROOT, as Visual Studio's Developer PowerShell sets it, or as a student sets it for
# a clone of vcpkg), none otherwise. A preset's toolchainFile cannot be left out when a variable is
# unset ("$env{VCPKG_ROOT}/scripts/buildsystems/vcpkg.cmake" would name /scripts/... and fail), so
# the presets name this file, and this file decides. With vcpkg, its manifest mode installs what
# vcpkg.json lists into the build folder while CMake configures.
#
# CMake reads a toolchain file again for each of its compiler checks, with the same environment,
# so the decision is the same each time; vcpkg.cmake guards itself against a second inclusion.
if(DEFINED ENV{VCPKG_ROOT} AND NOT "$ENV{VCPKG_ROOT}" STREQUAL "")
    file(TO_CMAKE_PATH "$ENV{VCPKG_ROOT}" raystep_vcpkg_root)
    if(NOT EXISTS "${raystep_vcpkg_root}/scripts/buildsystems/vcpkg.cmake")
        message(FATAL_ERROR "VCPKG_ROOT is ${raystep_vcpkg_root}, which holds no "
                            "scripts/buildsystems/vcpkg.cmake: set it to the folder of vcpkg, or "
                            "unset it to build with the libraries installed on this system")
    endif()
    include("${raystep_vcpkg_root}/scripts/buildsystems/vcpkg.cmake")
endif()
