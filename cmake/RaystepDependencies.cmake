# Third-party libraries, found once for the whole build.
#
# What a student's machine needs (Linux, macOS or Windows): GLM and Catch2 (v2 or v3) for the
# stage libraries and their tests; OpenImageIO, and the two small header-style libraries CLI11
# and tinyobjloader, for the `raystep` command that renders. CGAL, Embree and the rest are the
# instructor's: only the grader and the benchmarks use them.

# Each platform's list is a file of the repository: scripts/install-deps.sh (Debian's and Ubuntu's
# packages), Brewfile (Homebrew's formulae), vcpkg.json (vcpkg's ports, installed while the student
# presets configure when VCPKG_ROOT is set: cmake/RaystepVcpkg.cmake). README.md has the commands.
set(RAYSTEP_INSTALL_HINT
    "Debian/Ubuntu: scripts/install-deps.sh --student; macOS: brew bundle --no-upgrade (the Brewfile); Windows: set VCPKG_ROOT to your vcpkg, and the student presets install vcpkg.json's libraries (README.md)")

# GLM is headers only. Packagings of GLM 0.9.9 differ: some install a CMake configuration with
# glm::glm, some one whose target is plain `glm`, some none at all; the headers are all it takes.
find_package(glm CONFIG QUIET)
if(NOT TARGET glm::glm)
    find_path(RAYSTEP_GLM_INCLUDE_DIR glm/glm.hpp)
    if(NOT RAYSTEP_GLM_INCLUDE_DIR)
        message(FATAL_ERROR "GLM was not found. ${RAYSTEP_INSTALL_HINT}")
    endif()
    add_library(glm::glm INTERFACE IMPORTED)
    set_target_properties(glm::glm PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${RAYSTEP_GLM_INCLUDE_DIR})
endif()

find_package(Catch2 CONFIG QUIET)
if(NOT TARGET Catch2::Catch2WithMain)
    message(FATAL_ERROR "Catch2 was not found. ${RAYSTEP_INSTALL_HINT}")
endif()

# Debian's OpenImageIO CMake config names /usr/include/opencv4 and fails to configure where
# OpenCV's headers are absent, so pkg-config comes first and the CMake config is the fallback
# for platforms without pkg-config.
find_package(PkgConfig QUIET)
if(PkgConfig_FOUND)
    pkg_check_modules(OpenImageIO QUIET IMPORTED_TARGET OpenImageIO)
endif()
# OFF leaves the image module out: for a platform stand-in whose OpenImageIO cannot be had
# (release/standins/mingw-w64.cmake); every command that reads or writes an image then says so.
option(RAYSTEP_IMAGES "Build the image module (OpenImageIO)" ON)
add_library(raystep_openimageio INTERFACE)
if(TARGET PkgConfig::OpenImageIO)
    target_link_libraries(raystep_openimageio INTERFACE PkgConfig::OpenImageIO)
elseif(RAYSTEP_IMAGES)
    find_package(OpenImageIO CONFIG QUIET)
    if(NOT TARGET OpenImageIO::OpenImageIO)
        message(FATAL_ERROR "OpenImageIO was not found. ${RAYSTEP_INSTALL_HINT}")
    endif()
    target_link_libraries(raystep_openimageio INTERFACE OpenImageIO::OpenImageIO)
endif()

find_package(CLI11 CONFIG QUIET)
if(NOT TARGET CLI11::CLI11)
    message(FATAL_ERROR "CLI11 was not found. ${RAYSTEP_INSTALL_HINT}")
endif()

# Mesh coordinates are parsed straight to double, the precision of the whole student API, where
# the installed tinyobjloader offers it (Debian builds both variants); base/scene uses
# tinyobj::real_t, so either variant compiles.
find_package(tinyobjloader CONFIG QUIET)
add_library(raystep_tinyobjloader INTERFACE)
if(TARGET tinyobjloader::tinyobjloader_double)
    target_link_libraries(raystep_tinyobjloader INTERFACE tinyobjloader::tinyobjloader_double)
elseif(TARGET tinyobjloader::tinyobjloader)
    target_link_libraries(raystep_tinyobjloader INTERFACE tinyobjloader::tinyobjloader)
else()
    # We found no Homebrew formula of tinyobjloader (Brewfile), and another system may lack it
    # too: its source is fetched once into the build folder, pinned to the commit of its tag
    # v2.0.0rc13 (the version Debian 13 and vcpkg ship), and compiled with doubles. SOURCE_SUBDIR
    # names a folder with no CMakeLists.txt, so that only the one source file below is built.
    message(STATUS "tinyobjloader was not found: fetching its source (v2.0.0rc13) with git")
    include(FetchContent)
    FetchContent_Declare(raystep_tinyobjloader_source
        GIT_REPOSITORY https://github.com/tinyobjloader/tinyobjloader.git
        GIT_TAG 2945a967c5303b2c8c14174117c45f3302591150
        SOURCE_SUBDIR raystep-no-project)
    FetchContent_MakeAvailable(raystep_tinyobjloader_source)
    add_library(raystep_tinyobjloader_fetched STATIC
                ${raystep_tinyobjloader_source_SOURCE_DIR}/tiny_obj_loader.cc)
    target_include_directories(raystep_tinyobjloader_fetched SYSTEM
                               PUBLIC ${raystep_tinyobjloader_source_SOURCE_DIR})
    target_compile_definitions(raystep_tinyobjloader_fetched PUBLIC TINYOBJLOADER_USE_DOUBLE)
    target_link_libraries(raystep_tinyobjloader INTERFACE raystep_tinyobjloader_fetched)
endif()

find_package(Threads REQUIRED)

# cpp-httplib serves `raystep view`'s page. It is optional: a build without it has every other
# command, and `raystep view` says what to install. Debian ships it compiled, with a pkg-config
# file; Homebrew and vcpkg ship the header with a CMake configuration.
add_library(raystep_httplib INTERFACE)
if(PkgConfig_FOUND)
    pkg_check_modules(cpp-httplib QUIET IMPORTED_TARGET cpp-httplib)
endif()
if(TARGET PkgConfig::cpp-httplib)
    target_link_libraries(raystep_httplib INTERFACE PkgConfig::cpp-httplib)
    set(RAYSTEP_HAVE_VIEW_SERVER ON)
else()
    find_package(httplib CONFIG QUIET)
    if(TARGET httplib::httplib)
        target_link_libraries(raystep_httplib INTERFACE httplib::httplib)
        set(RAYSTEP_HAVE_VIEW_SERVER ON)
    else()
        set(RAYSTEP_HAVE_VIEW_SERVER OFF)
        message(STATUS "cpp-httplib not found: `raystep view` is left out. ${RAYSTEP_INSTALL_HINT}")
    endif()
endif()
