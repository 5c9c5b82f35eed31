# The near-field shell: one layer of prisms around the body (O-type), plus the root junction hexes (C-type), plus the wake block (H-type). Included from
# meshing/CMakeLists.txt; paths are relative to this file's folder.
find_package(OpenMP REQUIRED COMPONENTS CXX)  # the layer's per-node and per-triangle checks
add_library(semimesh_nearfield
  ${CMAKE_CURRENT_LIST_DIR}/src/nearfield/body_mesh.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/nearfield/node_normals.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/nearfield/layer_checks.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/nearfield/shell_common.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/nearfield/o_shell.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/nearfield/junction_geometry.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/nearfield/c_shell.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/nearfield/junction_block.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/nearfield/root_lift.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/nearfield/wing_layer.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/nearfield/h_shell.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/nearfield/wake_block.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/nearfield/fan_wedge.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/nearfield/skin_faces.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/nearfield/translational_rims.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/nearfield/root_corners.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/nearfield/pyramid_apex.cpp)
add_library(semimesh::nearfield ALIAS semimesh_nearfield)
target_include_directories(semimesh_nearfield PUBLIC ${CMAKE_CURRENT_LIST_DIR}/include)
target_link_libraries(semimesh_nearfield
  PUBLIC semimesh_mesh semimesh_surface_mesh semimesh_cadapi
  PRIVATE OpenMP::OpenMP_CXX semimesh_warnings)
set_target_properties(semimesh_nearfield PROPERTIES POSITION_INDEPENDENT_CODE ON)
