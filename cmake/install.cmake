# `cmake --install` gives the library as a CMake package: headers, the static libraries of every
# part as imported targets semimesh::<part> (semimesh::cadapi, semimesh::pipeline, ...) and
# semimeshConfig.cmake, so `find_package(semimesh)` works (examples/embed). The far field
# (semimesh::farfield) links TetGen, AGPL-3.0-or-later; the other parts do not.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# Every library target of the parts, found by walking their folders (a new target is exported
# without a list to keep up to date).
function(semimesh_collect_libraries directory out)
  get_property(targets DIRECTORY ${directory} PROPERTY BUILDSYSTEM_TARGETS)
  get_property(children DIRECTORY ${directory} PROPERTY SUBDIRECTORIES)
  set(found)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    if(type MATCHES "LIBRARY$" AND target MATCHES "^semimesh_" AND NOT target STREQUAL "semimesh_cli")
      list(APPEND found ${target})
    endif()
  endforeach()
  foreach(child IN LISTS children)
    semimesh_collect_libraries(${child} child_found)
    list(APPEND found ${child_found})
  endforeach()
  set(${out} ${found} PARENT_SCOPE)
endfunction()

set(semimesh_exported semimesh_warnings)
foreach(part cadapi mock_cad backends highorder meshing io pipeline)
  semimesh_collect_libraries(${PROJECT_SOURCE_DIR}/${part} part_libraries)
  list(APPEND semimesh_exported ${part_libraries})
endforeach()

# Public include folders inside the source tree: used from there when building, from the installed
# include/ when installed.
foreach(target IN LISTS semimesh_exported)
  string(REGEX REPLACE "^semimesh_" "" export_name ${target})
  set_property(TARGET ${target} PROPERTY EXPORT_NAME ${export_name})
  get_target_property(dirs ${target} INTERFACE_INCLUDE_DIRECTORIES)
  if(NOT dirs)
    continue()
  endif()
  set(interface)
  foreach(dir IN LISTS dirs)
    if(dir MATCHES "^\\$<" OR NOT IS_ABSOLUTE "${dir}" OR NOT dir MATCHES "^${PROJECT_SOURCE_DIR}/")
      list(APPEND interface "${dir}")
    else()
      list(APPEND interface "$<BUILD_INTERFACE:${dir}>")
      install(DIRECTORY "${dir}/" DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
    endif()
  endforeach()
  list(APPEND interface "$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>")
  set_property(TARGET ${target} PROPERTY INTERFACE_INCLUDE_DIRECTORIES "${interface}")
endforeach()

install(TARGETS ${semimesh_exported} EXPORT semimeshTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS semimesh RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(EXPORT semimeshTargets NAMESPACE semimesh:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/semimesh)
set(SEMIMESH_PACKAGE_HAS_OCC OFF)
if(TARGET semimesh_occ)
  set(SEMIMESH_PACKAGE_HAS_OCC ON)
endif()
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/semimeshConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/semimeshConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/semimesh)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/semimeshConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/semimeshConfig.cmake ${PROJECT_BINARY_DIR}/semimeshConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/semimesh)
