# sf_add_filter(<node name> <configuration header> [NO_INSTALL])
#
# Builds a fusion node executable from one configuration header (see doc/configuration.md)
# and installs it into the package's lib/ folder (rosrun), unless NO_INSTALL is given (a node
# only for tests). Exported through catkin: a package that find_package()s sf_pkg can call it
# with its own headers. The header path is relative to the calling CMakeLists.txt or absolute.
if(NOT DEFINED SF_PKG_FILTER_MAIN)
  # Inside sf_pkg itself, or installed (share/sf_pkg mirrors the source tree): the main is
  # beside this file's directory.
  get_filename_component(_sf_pkg_root "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)
  if(NOT EXISTS "${_sf_pkg_root}/sf_filter/src/fusion_node_main.cpp")
    # Devel space: catkin puts this file in devel/share/sf_pkg/cmake; the main stays in
    # the source tree.
    set(_sf_pkg_root "${sf_pkg_SOURCE_PREFIX}")
  endif()
  set(SF_PKG_FILTER_MAIN "${_sf_pkg_root}/sf_filter/src/fusion_node_main.cpp")
endif()

# Installed, the headers (sf_filter/, sf_estimation/) are in the package's own include folder,
# <prefix>/include/sf_pkg, and keep their #include <sf_filter/...> names: that folder is added
# to sf_pkg's include directories (catkin exports only <prefix>/include). Devel space and
# in-tree builds use the source folders (catkin_package(INCLUDE_DIRS)).
get_filename_component(_sf_pkg_installed_include "${CMAKE_CURRENT_LIST_DIR}/../../../include/sf_pkg"
  ABSOLUTE)
if(CMAKE_CURRENT_LIST_DIR MATCHES "/share/sf_pkg/cmake$"
   AND EXISTS "${_sf_pkg_installed_include}/sf_filter")
  list(APPEND sf_pkg_INCLUDE_DIRS "${_sf_pkg_installed_include}")
endif()

function(sf_add_filter name header)
  cmake_parse_arguments(_sf "NO_INSTALL" "" "" ${ARGN})
  if(_sf_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "sf_add_filter(${name}): unknown arguments ${_sf_UNPARSED_ARGUMENTS}")
  endif()
  get_filename_component(_header "${header}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
  if(NOT EXISTS "${_header}")
    message(FATAL_ERROR "sf_add_filter(${name}): configuration header ${_header} not found")
  endif()
  # The header's translation unit is an object library that waits only for the message
  # headers: make compiles an executable's sources only after every library it links is
  # built, which in a clean build would hold every node back until the package's libraries
  # are done (doc/build_cost.md). It takes the libraries' include directories and
  # definitions from their properties instead of linking them, as linking orders the build.
  set(_unit ${name}_unit)
  add_library(${_unit} OBJECT "${SF_PKG_FILTER_MAIN}")
  target_compile_definitions(${_unit} PRIVATE SF_CONFIG_HEADER="${_header}")
  target_compile_features(${_unit} PRIVATE cxx_std_17)
  # A node is optimised unless the caller asks for a build type: a catkin workspace configured
  # without CMAKE_BUILD_TYPE compiles with no -O at all, which makes a filter step 100x slower.
  if(NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
    target_compile_options(${_unit} PRIVATE -O2)
    target_compile_definitions(${_unit} PRIVATE NDEBUG)
  endif()
  # Configuration mistakes are reported by #error/static_assert naming the macro; the
  # macro-expansion backtrace under each would only bury that message.
  target_compile_options(${_unit} PRIVATE $<$<CXX_COMPILER_ID:GNU>:-ftrack-macro-expansion=0>)
  target_include_directories(${_unit} PRIVATE ${catkin_INCLUDE_DIRS} ${sf_pkg_INCLUDE_DIRS})
  add_executable(${name} $<TARGET_OBJECTS:${_unit}>)
  target_link_libraries(${name} ${catkin_LIBRARIES} ${sf_pkg_LIBRARIES})
  if(TARGET sf_fusion_node)
    target_link_libraries(${name} sf_fusion_node)
    target_include_directories(${_unit} PRIVATE
      $<TARGET_PROPERTY:sf_fusion_node,INTERFACE_INCLUDE_DIRECTORIES>)
    target_compile_definitions(${_unit} PRIVATE
      $<TARGET_PROPERTY:sf_fusion_node,INTERFACE_COMPILE_DEFINITIONS>)
    target_link_libraries(${_unit} PRIVATE Eigen3::Eigen Boost::headers)  # imported: no order
  endif()
  # The message headers (sf_msgs) are generated before the node compiles when sf_msgs is in
  # the same workspace (catkin defines empty targets for installed packages).
  if(catkin_EXPORTED_TARGETS)
    add_dependencies(${_unit} ${catkin_EXPORTED_TARGETS})
  endif()
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY
    "${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_BIN_DESTINATION}")
  if(NOT _sf_NO_INSTALL)
    install(TARGETS ${name} RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
  endif()
endfunction()
