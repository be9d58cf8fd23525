# sf_add_filter(<node name> <configuration header> [NO_INSTALL | TEST] [NODELET <plugin xml>])
#
# Builds a fusion node executable from one configuration header (see doc/configuration.md)
# and installs it into the package's lib/ folder (rosrun), unless NO_INSTALL is given (a node
# that is not installed) or TEST (a node only for tests: not installed either, and built with
# the tests, by catkin's `tests` and `run_tests` targets, not by `all`). Exported through
# catkin: a package that find_package()s sf_pkg can call it with its own headers. The header
# path is relative to the calling CMakeLists.txt or absolute.
#
# NODELET <plugin xml>: also the nodelet plugin library lib<node name>_nodelet with the class
# sf_nodelets::<node name> (doc/filter_node.md#nodelet). The header's translation unit is
# compiled once, position-independent, for the node and the plugin. <plugin xml> is the
# package's nodelet plugin description (exported in package.xml); the build fails if it lacks
# the plugin's entry, and prints the entry to add.
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
get_filename_component(_sf_pkg_src "${SF_PKG_FILTER_MAIN}" DIRECTORY)
set(SF_PKG_NODELET_UNIT "${_sf_pkg_src}/fusion_node_unit.cpp")
set(SF_PKG_FILTER_SMOOTHERS "${_sf_pkg_src}/fusion_node_smoothers.cpp")
set(SF_PKG_FILTER_STEP "${_sf_pkg_src}/fusion_node_step.cpp")
set(SF_PKG_FILTER_JACOBIANS "${_sf_pkg_src}/fusion_node_jacobians.cpp")
set(SF_PKG_NODELET_PLUGIN "${_sf_pkg_src}/fusion_nodelet_plugin.cpp")

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

option(SF_PKG_PRECOMPILED_PRELUDE
  "Precompile sf_filter/node_unit_prelude.hpp once per package for the nodes' units" ON)

# The compile settings of a header's translation unit (the node's, or the object library the
# node and its nodelet share).
function(_sf_filter_unit target header)
  target_compile_definitions(${target} PRIVATE SF_CONFIG_HEADER="${header}")
  _sf_filter_unit_flags(${target})
  _sf_filter_prelude(${target})
endfunction()

# Everything of a unit's compile command but the header: the precompiled prelude is valid for
# a unit only when both are compiled with the same options and definitions (GCC checks, and
# falls back to parsing the prelude, with a -Winvalid-pch warning, when they differ).
function(_sf_filter_unit_flags target)
  target_compile_features(${target} PRIVATE cxx_std_17)
  # A node is optimised unless the caller asks for a build type: a catkin workspace configured
  # without CMAKE_BUILD_TYPE compiles with no -O at all, which makes a filter step 100x slower.
  if(NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
    target_compile_options(${target} PRIVATE -O2)
    target_compile_definitions(${target} PRIVATE NDEBUG)
  endif()
  # Configuration mistakes are reported by #error/static_assert naming the macro; the
  # macro-expansion backtrace under each would only bury that message.
  target_compile_options(${target} PRIVATE $<$<CXX_COMPILER_ID:GNU>:-ftrack-macro-expansion=0>)
  # GCC collects its garbage when its heap has grown by half since the last collection, not by
  # all of it (its default with more than 1 GB of memory): the particle filter's unit peaked at
  # 503-509 MB, over the 500 MB budget of a unit, and stays under it (doc/build_cost.md, "GCC's
  # garbage collection"). The object code is the same (compared with cmp).
  target_compile_options(${target} PRIVATE $<$<CXX_COMPILER_ID:GNU>:--param=ggc-min-expand=50>)
  # Every unit is position-independent, so that one precompiled prelude serves the nodes and
  # the nodelets (Debian's g++ builds executables position-independent anyway).
  set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  _sf_filter_includes(${target})
  if(TARGET sf_fusion_node)
    target_link_libraries(${target} PRIVATE Eigen3::Eigen Boost::headers)  # imported: no order
  endif()
endfunction()

# Targets only tests use: built by catkin's `tests` target (which `run_tests` builds), not by
# `all`, so that a package's build compiles what it ships.
function(_sf_build_with_tests)
  set_target_properties(${ARGN} PROPERTIES EXCLUDE_FROM_ALL TRUE)
  if(NOT TARGET tests)
    add_custom_target(tests)
  endif()
  add_dependencies(tests ${ARGN})
endfunction()

# The prelude (sf_filter/node_unit_prelude.hpp: Eigen, ROS serialization, the common messages,
# the filters, the fusion core) is precompiled once per package, by the first sf_add_filter()
# call, and force-included in every unit of the package: parsing it was 40 % of a unit's
# compile time (doc/build_cost.md). Off with -DSF_PKG_PRECOMPILED_PRELUDE=OFF or CMake's
# CMAKE_DISABLE_PRECOMPILE_HEADERS; the units then include the same headers themselves.
function(_sf_filter_prelude target)
  if(NOT SF_PKG_PRECOMPILED_PRELUDE OR CMAKE_DISABLE_PRECOMPILE_HEADERS)
    return()
  endif()
  set(_prelude ${PROJECT_NAME}_sf_filter_prelude)
  if(NOT TARGET ${_prelude})
    set(_source "${CMAKE_CURRENT_BINARY_DIR}/${_prelude}.cpp")
    file(CONFIGURE OUTPUT "${_source}"
      CONTENT "// The target that precompiles sf_filter/node_unit_prelude.hpp.\n")
    add_library(${_prelude} OBJECT "${_source}")
    _sf_filter_unit_flags(${_prelude})
    target_precompile_headers(${_prelude} PRIVATE <sf_filter/node_unit_prelude.hpp>)
  endif()
  target_precompile_headers(${target} REUSE_FROM ${_prelude})
endfunction()

function(_sf_filter_includes target)
  target_include_directories(${target} PRIVATE ${catkin_INCLUDE_DIRS} ${sf_pkg_INCLUDE_DIRS})
  if(TARGET sf_fusion_node)
    # In sf_pkg's own build: the library's include directories and definitions from its
    # properties, not by linking it (an object library that linked it would wait for it).
    target_include_directories(${target} PRIVATE
      $<TARGET_PROPERTY:sf_fusion_node,INTERFACE_INCLUDE_DIRECTORIES>)
    target_compile_definitions(${target} PRIVATE
      $<TARGET_PROPERTY:sf_fusion_node,INTERFACE_COMPILE_DEFINITIONS>
      $<TARGET_PROPERTY:sf_estimation,INTERFACE_COMPILE_DEFINITIONS>)
  else()
    # Installed: the Eigen setting that sf_estimation's target carries
    # (SF_ESTIMATION_EIGEN_DEFINITIONS in sf_estimation/CMakeLists.txt), which catkin's
    # exported variables do not.
    target_compile_definitions(${target} PRIVATE EIGEN_CACHEFRIENDLY_PRODUCT_THRESHOLD=16)
  endif()
  # The message headers (sf_msgs) are generated before the node compiles when sf_msgs is in
  # the same workspace (catkin defines empty targets for installed packages).
  if(catkin_EXPORTED_TARGETS)
    add_dependencies(${target} ${catkin_EXPORTED_TARGETS})
  endif()
endfunction()

function(_sf_filter_link target)
  target_link_libraries(${target} ${catkin_LIBRARIES} ${sf_pkg_LIBRARIES})
  if(TARGET sf_fusion_node)
    target_link_libraries(${target} sf_fusion_node)
  endif()
endfunction()

function(sf_add_filter name header)
  cmake_parse_arguments(_sf "NO_INSTALL;TEST" "NODELET" "" ${ARGN})
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
  # are done (doc/build_cost.md). With NODELET it is compiled once for the node and the
  # plugin. The header's smoothers are a second unit of the same object library, compiled
  # beside the first (fusion_node_smoothers.cpp, doc/build_cost.md "The smoothers' unit"), and
  # a 3D header's filter step a third (fusion_node_step.cpp, "The 3D headers' step"), only for
  # a header that names QUATERNION_STATES: for any other it would be empty. An EKF's AutoDiff
  # Jacobians are a fourth (fusion_node_jacobians.cpp, "The Jacobians' unit"), for a header that
  # names EXTENDED_KALMAN_FILTER or QUATERNION_STATES.
  set(_unit ${name}_unit)
  if(_sf_NODELET)
    _sf_check_nodelet_xml(${name} "${_sf_NODELET}")
    set(_sources "${SF_PKG_NODELET_UNIT}" "${SF_PKG_FILTER_SMOOTHERS}")
  else()
    set(_sources "${SF_PKG_FILTER_MAIN}" "${SF_PKG_FILTER_SMOOTHERS}")
  endif()
  _sf_header_names(_step "${_header}" QUATERNION_STATES)
  _sf_header_names(_jacobians "${_header}" EXTENDED_KALMAN_FILTER)
  if(_step)
    list(APPEND _sources "${SF_PKG_FILTER_STEP}")
  endif()
  if(_step OR _jacobians)
    list(APPEND _sources "${SF_PKG_FILTER_JACOBIANS}")
  endif()
  add_library(${_unit} OBJECT ${_sources})
  _sf_filter_unit(${_unit} "${_header}")
  # The node unit then declares the smoothers extern (node_definition_of.hpp); any other unit
  # of a header (tests, tools) instantiates them itself. SF_FILTER_STEP_UNIT: the third unit is
  # there, and the fourth (without them, a header that has QUATERNION_STATES after all stops at
  # an #error). SF_FILTER_JACOBIAN_UNIT: the fourth is there (without it the Jacobians are
  # compiled where they are used).
  target_compile_definitions(${_unit} PRIVATE SF_FILTER_SMOOTHERS_UNIT=1)
  if(_step)
    target_compile_definitions(${_unit} PRIVATE SF_FILTER_STEP_UNIT=1)
  endif()
  if(_step OR _jacobians)
    target_compile_definitions(${_unit} PRIVATE SF_FILTER_JACOBIAN_UNIT=1)
  endif()
  add_executable(${name} $<TARGET_OBJECTS:${_unit}>)
  if(_sf_TEST)
    set(_sf_NO_INSTALL TRUE)
    _sf_build_with_tests(${_unit} ${name})
  endif()
  if(_sf_NODELET)
    add_library(${name}_nodelet SHARED "${SF_PKG_NODELET_PLUGIN}" $<TARGET_OBJECTS:${_unit}>)
    target_compile_definitions(${name}_nodelet PRIVATE SF_NODELET_CLASS=${name})
    target_compile_features(${name}_nodelet PRIVATE cxx_std_17)
    _sf_filter_includes(${name}_nodelet)
    _sf_filter_link(${name}_nodelet)
    find_package(nodelet REQUIRED)
    find_package(pluginlib REQUIRED)
    target_include_directories(${name}_nodelet PRIVATE ${nodelet_INCLUDE_DIRS}
      ${pluginlib_INCLUDE_DIRS})
    target_link_libraries(${name}_nodelet ${nodelet_LIBRARIES} ${pluginlib_LIBRARIES})
    # Every header's plugin defines the same symbols (headerDefinition(), the sf_config types'
    # template instances and vtables) with different contents. A manager loading two plugins
    # would otherwise bind the second library's references to the first one's definitions
    # (ELF interposition) and run the first header twice; -Bsymbolic binds each plugin's
    # references to its own definitions.
    target_link_options(${name}_nodelet PRIVATE "LINKER:-Bsymbolic")
    set_target_properties(${name}_nodelet PROPERTIES LIBRARY_OUTPUT_DIRECTORY
      "${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_LIB_DESTINATION}")
    if(_sf_TEST)
      _sf_build_with_tests(${name}_nodelet)
    elseif(NOT _sf_NO_INSTALL)
      install(TARGETS ${name}_nodelet LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})
    endif()
  endif()
  _sf_filter_link(${name})
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY
    "${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_BIN_DESTINATION}")
  if(NOT _sf_NO_INSTALL)
    install(TARGETS ${name} RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
  endif()
endfunction()

# Sets <out> to whether <macro> occurs in the header or in a header it includes by "..." (found
# beside the including file, where the preprocessor looks first), a comment included: a
# configure-time look that errs toward TRUE. Headers that name the macro only through an
# <...> include are not followed; node_definition_of.hpp stops those with an #error.
function(_sf_header_names out header macro)
  set(_todo "${header}")
  set(_seen)
  while(_todo)
    list(POP_FRONT _todo _file)
    list(FIND _seen "${_file}" _index)
    if(NOT _index EQUAL -1 OR NOT EXISTS "${_file}")
      continue()
    endif()
    list(APPEND _seen "${_file}")
    file(STRINGS "${_file}" _hits REGEX "${macro}")
    if(_hits)
      set(${out} TRUE PARENT_SCOPE)
      return()
    endif()
    file(STRINGS "${_file}" _includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
    get_filename_component(_dir "${_file}" DIRECTORY)
    foreach(_line IN LISTS _includes)
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]+)\".*$" "\\1" _name "${_line}")
      get_filename_component(_path "${_name}" ABSOLUTE BASE_DIR "${_dir}")
      list(APPEND _todo "${_path}")
    endforeach()
  endwhile()
  set(${out} FALSE PARENT_SCOPE)
endfunction()

# The plugin description must name the plugin's library and class, or pluginlib would not find
# it at run time (nodelet load: "class ... not found").
function(_sf_check_nodelet_xml name xml)
  get_filename_component(_xml "${xml}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
  set(_entry "<library path=\"lib/lib${name}_nodelet\">
  <class name=\"${PROJECT_NAME}/${name}\" type=\"sf_nodelets::${name}\"
         base_class_type=\"nodelet::Nodelet\">
    <description>...</description>
  </class>
</library>")
  if(NOT EXISTS "${_xml}")
    message(FATAL_ERROR "sf_add_filter(${name} ... NODELET ${xml}): ${_xml} not found; it "
      "should hold (inside <class_libraries>):\n${_entry}")
  endif()
  file(READ "${_xml}" _text)
  string(FIND "${_text}" "\"lib/lib${name}_nodelet\"" _library)
  string(FIND "${_text}" "\"sf_nodelets::${name}\"" _class)
  if(_library EQUAL -1 OR _class EQUAL -1)
    message(FATAL_ERROR "sf_add_filter(${name} ... NODELET ${xml}): ${_xml} has no entry for "
      "the plugin; add (inside <class_libraries>):\n${_entry}")
  endif()
endfunction()
