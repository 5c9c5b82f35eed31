# Certified Jacobian bounds and element quality (included by highorder/CMakeLists.txt).
target_sources(semimesh_highorder PRIVATE
  ${CMAKE_CURRENT_SOURCE_DIR}/src/validity/bernstein.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/validity/jacobian_polynomial.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/validity/affine_jacobian.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/validity/trilinear_jacobian.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/validity/certify_jacobian.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/validity/certify_pieces.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/validity/sample_jacobian.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/validity/quality.cpp)
