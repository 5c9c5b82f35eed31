# `semimesh run` as a library: configuration (TOML), the stage-by-stage pipeline, the mesh checks
# and the report. Included from meshing/CMakeLists.txt; paths are relative to this file's folder.
# The checks need only the mesh and surface data models; the pipeline needs every stage (semimesh_io
# is defined later, in io/, and linked by name; semimesh_ho_mesh comes from highorder/, added first).
find_package(Threads REQUIRED)
add_library(semimesh_checks
  ${CMAKE_CURRENT_LIST_DIR}/src/checks/face_nodes.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/checks/conformity.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/checks/volume.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/checks/validity.cpp)
add_library(semimesh::checks ALIAS semimesh_checks)
target_include_directories(semimesh_checks PUBLIC ${CMAKE_CURRENT_LIST_DIR}/include)
target_link_libraries(semimesh_checks PUBLIC semimesh_meshing semimesh_highorder semimesh_surface_mesh
                                      PRIVATE fmt::fmt Threads::Threads semimesh_warnings)

find_package(tomlplusplus REQUIRED)
add_library(semimesh_config ${CMAKE_CURRENT_LIST_DIR}/src/pipeline/config.cpp)
target_include_directories(semimesh_config PUBLIC ${CMAKE_CURRENT_LIST_DIR}/include)
target_link_libraries(semimesh_config PRIVATE tomlplusplus::tomlplusplus fmt::fmt semimesh_warnings)

if(TARGET semimesh_nearfield AND TARGET semimesh_farfield AND TARGET semimesh_ho_mesh)
  add_library(semimesh_pipeline
    ${CMAKE_CURRENT_LIST_DIR}/src/pipeline/pipeline.cpp
    ${CMAKE_CURRENT_LIST_DIR}/src/pipeline/split_stacks.cpp
    ${CMAKE_CURRENT_LIST_DIR}/src/pipeline/report.cpp)
  add_library(semimesh::pipeline ALIAS semimesh_pipeline)
  target_include_directories(semimesh_pipeline PUBLIC ${CMAKE_CURRENT_LIST_DIR}/include)
  target_link_libraries(semimesh_pipeline
    PUBLIC semimesh_config semimesh_checks semimesh_meshing semimesh_ho_mesh
    PRIVATE semimesh_backends semimesh_surface_mesh semimesh_nearfield semimesh_farfield semimesh_io
            fmt::fmt
            semimesh_warnings)
endif()
