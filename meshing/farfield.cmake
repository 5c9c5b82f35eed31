# The far field: wall annulus, box faces, pyramids on skin quads, TetGen tetrahedra.
# Licence: TetGen 1.5 is AGPL-3.0-or-later; it is linked by this target only, so users who do not
# build the far field do not take it on. (CGAL's Triangulation_2, GPL-3.0-or-later, is used here
# and by semimesh_surface_mesh.)
# Debian's libtet1.5-dev ships a header and a library but no CMake config.
find_package(CGAL REQUIRED)
find_package(OpenMP REQUIRED COMPONENTS CXX)  # the interior points' octree cells
find_path(TETGEN_INCLUDE_DIR tetgen.h REQUIRED)
find_library(TET_LIBRARY tet REQUIRED)
add_library(semimesh_farfield
  ${CMAKE_CURRENT_LIST_DIR}/src/farfield/wall_annulus.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/farfield/wall_layer.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/farfield/pyramid_apex.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/farfield/boundary_crossing.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/farfield/interior_points.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/farfield/short_edge.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/farfield/flat_tet.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/farfield/untie_boundary.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/farfield/symmetry_faces.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/farfield/tetgen_volume.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/farfield/far_field.cpp)
add_library(semimesh::farfield ALIAS semimesh_farfield)
target_include_directories(semimesh_farfield PUBLIC ${CMAKE_CURRENT_LIST_DIR}/include
                                             PRIVATE ${TETGEN_INCLUDE_DIR})
target_link_libraries(semimesh_farfield PUBLIC semimesh_nearfield semimesh_mesh semimesh_cadapi
                                        PRIVATE semimesh_surface_mesh CGAL::CGAL ${TET_LIBRARY} OpenMP::OpenMP_CXX semimesh_warnings)
set_target_properties(semimesh_farfield PROPERTIES POSITION_INDEPENDENT_CODE ON)
