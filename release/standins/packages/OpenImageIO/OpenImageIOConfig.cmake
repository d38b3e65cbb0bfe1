# OpenImageIO for the libc++ stand-in (release/standins/libcxx.cmake): Debian's, built against
# libstdc++, so whatever links it (the image module alone) is compiled and linked against
# libstdc++ too. The module and the programs share nothing but a plain C table.
find_library(RAYSTEP_STANDIN_OIIO OpenImageIO)
find_library(RAYSTEP_STANDIN_OIIO_UTIL OpenImageIO_Util)
if(NOT RAYSTEP_STANDIN_OIIO OR NOT RAYSTEP_STANDIN_OIIO_UTIL)
    set(OpenImageIO_FOUND FALSE)
    return()
endif()
add_library(OpenImageIO::OpenImageIO INTERFACE IMPORTED)
set_target_properties(OpenImageIO::OpenImageIO PROPERTIES
    INTERFACE_COMPILE_OPTIONS -stdlib=libstdc++
    INTERFACE_LINK_OPTIONS -stdlib=libstdc++
    INTERFACE_LINK_LIBRARIES "${RAYSTEP_STANDIN_OIIO};${RAYSTEP_STANDIN_OIIO_UTIL}")
