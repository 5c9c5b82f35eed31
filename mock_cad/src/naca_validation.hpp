// Checks of NacaWingParams shared by the parameter reader and the model builder. Every error is a
// cad::CadError(BadParameter) that names the naca.* key, its value and what was expected.
#pragma once

#include "naca_section.hpp"

#include "semimesh/mock_cad/naca.hpp"

#include <string>

namespace semimesh::mock_cad::detail {

/// The digits of a 4-digit code "MPTT"; throws naming naca.code.
NacaDigits parse_naca_code(const std::string& code);

/// Throws on the first invalid field.
void validate(const NacaWingParams& params);

}  // namespace semimesh::mock_cad::detail
