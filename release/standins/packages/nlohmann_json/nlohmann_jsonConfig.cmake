# nlohmann/json for a stand-in (release/standins/): its headers alone (the version beside this).
include(${CMAKE_CURRENT_LIST_DIR}/../standin_headers.cmake)
raystep_standin_interface(nlohmann_json::nlohmann_json nlohmann)
