#pragma once
// Asserts that a statement throws hyst::Error whose message contains the given text.

#include <string>

#include <gtest/gtest.h>

#include "hyst/core/error.hpp"

#define EXPECT_HYST_ERROR(statement, expected_text)                                            \
  do {                                                                                         \
    try {                                                                                      \
      statement;                                                                               \
      ADD_FAILURE() << "expected hyst::Error containing \"" << (expected_text)                 \
                    << "\", but nothing was thrown";                                           \
    } catch (const hyst::Error& error) {                                                       \
      EXPECT_NE(std::string(error.what()).find(expected_text), std::string::npos)              \
          << "message: \"" << error.what() << "\"\nexpected to contain: \"" << (expected_text) \
          << "\"";                                                                             \
    }                                                                                          \
  } while (false)
