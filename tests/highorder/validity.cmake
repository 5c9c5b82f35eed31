# Certified Jacobian bounds (included by tests/highorder/CMakeLists.txt).
semimesh_add_gtest(test_ho_validity
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/validity_bernstein.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/validity_jacobian.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/validity_pieces.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/validity_determinant.cpp
  LIBS semimesh_highorder)
# validity_determinant.cpp tests a header private to the library (validity/jacobian_polynomial.hpp).
target_include_directories(test_ho_validity PRIVATE ${PROJECT_SOURCE_DIR}/highorder/src)
