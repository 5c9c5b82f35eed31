# The mesh checks: conformity, volume, certified validity. Included from meshing/CMakeLists.txt;
# paths are relative to this file's folder.
find_package(Threads REQUIRED)
add_library(semimesh_checks
  ${CMAKE_CURRENT_LIST_DIR}/src/checks/face_nodes.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/checks/conformity.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/checks/volume.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/checks/validity.cpp)
add_library(semimesh::checks ALIAS semimesh_checks)
target_include_directories(semimesh_checks PUBLIC ${CMAKE_CURRENT_LIST_DIR}/include)
target_link_libraries(semimesh_checks PUBLIC semimesh_mesh semimesh_highorder semimesh_surface_mesh
                                      PRIVATE semimesh_ho_mesh fmt::fmt Threads::Threads semimesh_warnings)
