# 1D/2D meshing on CAD: size field, curve discretisation, surface meshes in parameter space.
# Included from meshing/CMakeLists.txt; paths are relative to this file's folder.
find_package(CGAL REQUIRED)
find_package(OpenMP REQUIRED COMPONENTS CXX)  # the shell limits' sample rows
add_library(semimesh_surface_mesh
  ${CMAKE_CURRENT_LIST_DIR}/src/surface/size_field.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/surface/shell_size_limit.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/surface/curve_discretisation.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/surface/boundary_nodes.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/surface/parameter_triangulation.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/surface/mesh_improvement.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/surface/flat_corners.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/surface/mesh_surface.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/surface/structured_surface.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/surface/strip_counts.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/surface/mesh_quality.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/surface/model_surfaces.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/surface/cad_roles.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/surface/root_plane.cpp)
add_library(semimesh::surface_mesh ALIAS semimesh_surface_mesh)
target_include_directories(semimesh_surface_mesh PUBLIC ${CMAKE_CURRENT_LIST_DIR}/include)
target_link_libraries(semimesh_surface_mesh PUBLIC semimesh_cadapi PRIVATE CGAL::CGAL fmt::fmt OpenMP::OpenMP_CXX semimesh_warnings)
set_target_properties(semimesh_surface_mesh PROPERTIES POSITION_INDEPENDENT_CODE ON)
