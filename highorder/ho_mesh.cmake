# High order on meshes: CAD curving with spring optimisation, isoparametric layer splitting, whole-mesh
# certification and repair. A separate target from semimesh_highorder because it needs the mesh model
# (semimesh_mesh links semimesh_highorder) and the CAD interface. The element-local passes run over
# OpenMP threads (results independent of the thread count).
find_package(OpenMP REQUIRED COMPONENTS CXX)
add_library(semimesh_ho_mesh
  ${CMAKE_CURRENT_LIST_DIR}/src/splitting/reference_lattice.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/splitting/split_layers.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/splitting/sparse_rows.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/splitting/lattice_lines.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/splitting/layer_keys.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/splitting/pyramid_columns.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/splitting/precut_faces.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/curving/harmonic_extension.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/curving/cad_classification.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/curving/pole_chart.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/curving/kinked_parameters.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/curving/spring_optimisation.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/curving/curve_mesh.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/curving/follow_exposed_body.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/curving/geometric_error.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/mesh_validity/certify_mesh.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/repair/repair_invalid.cpp)
add_library(semimesh::ho_mesh ALIAS semimesh_ho_mesh)
target_include_directories(semimesh_ho_mesh PUBLIC ${CMAKE_CURRENT_LIST_DIR}/include
                                            PRIVATE ${CMAKE_CURRENT_LIST_DIR}/src)
target_link_libraries(semimesh_ho_mesh PUBLIC semimesh_mesh semimesh_highorder semimesh_cadapi Eigen3::Eigen
                                       PRIVATE OpenMP::OpenMP_CXX semimesh_warnings)
