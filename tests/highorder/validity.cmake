# Certified Jacobian bounds (included by tests/highorder/CMakeLists.txt).
semimesh_add_gtest(test_ho_validity
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/validity_bernstein.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/validity_jacobian.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/validity_pieces.cpp
  LIBS semimesh_highorder)
