# FindStb: Debian's libstb-dev (headers under stb/, implementations in libstb).
# Defines Stb::Stb. Set STB_STATIC=ON to prefer libstb.a (for builds carried to other machines).
find_path(STB_INCLUDE_DIR stb_image_write.h PATH_SUFFIXES stb)
if(STB_STATIC)
  find_library(STB_LIBRARY NAMES libstb.a stb)
else()
  find_library(STB_LIBRARY NAMES stb)
endif()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Stb REQUIRED_VARS STB_INCLUDE_DIR STB_LIBRARY
  REASON_FAILURE_MESSAGE "install Debian's libstb-dev (tools/setup.sh does)")
if(Stb_FOUND AND NOT TARGET Stb::Stb)
  add_library(Stb::Stb UNKNOWN IMPORTED)
  set_target_properties(Stb::Stb PROPERTIES IMPORTED_LOCATION "${STB_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${STB_INCLUDE_DIR}")
endif()
mark_as_advanced(STB_INCLUDE_DIR STB_LIBRARY)
