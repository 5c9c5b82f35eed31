// Asserts that a call throws cad::CadError of a given kind whose message contains given text.
#pragma once

#include "semimesh/cad/error.hpp"

#include <gtest/gtest.h>

#include <string>

template <class Call>
void expect_cad_error(Call&& call, semimesh::cad::CadError::Kind kind, const std::string& text) {
  try {
    call();
    ADD_FAILURE() << "expected a CadError containing '" << text << "', nothing was thrown";
  } catch (const semimesh::cad::CadError& e) {
    EXPECT_EQ(static_cast<int>(e.kind()), static_cast<int>(kind)) << e.what();
    EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << "message: " << e.what() << "\nexpected to contain: " << text;
  }
}
