# CLI11 for a stand-in (release/standins/): its headers alone.
include(${CMAKE_CURRENT_LIST_DIR}/../standin_headers.cmake)
raystep_standin_interface(CLI11::CLI11 CLI)
