# find_package(fresnel) for an installed fresnel (`make install`): the
# imported target fresnel::fresnel (libfresnel.a, its headers and libm).
# Found relative to this file, so the installed tree may be moved.
get_filename_component(_fresnel_prefix "${CMAKE_CURRENT_LIST_DIR}/../../.." ABSOLUTE)
if(NOT TARGET fresnel::fresnel)
    add_library(fresnel::fresnel STATIC IMPORTED)
    set_target_properties(fresnel::fresnel PROPERTIES
        IMPORTED_LOCATION "${_fresnel_prefix}/lib/libfresnel.a"
        IMPORTED_LINK_INTERFACE_LANGUAGES C
        INTERFACE_INCLUDE_DIRECTORIES "${_fresnel_prefix}/include")
    if(UNIX)
        set_property(TARGET fresnel::fresnel PROPERTY INTERFACE_LINK_LIBRARIES m)
    endif()
endif()
set(fresnel_DATA_DIR "${_fresnel_prefix}/share/fresnel/data")
set(fresnel_GLSL_DIR "${_fresnel_prefix}/share/fresnel/glsl")
unset(_fresnel_prefix)
