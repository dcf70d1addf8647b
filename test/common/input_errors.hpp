// The one check of the model tests that a bad input is rejected as the input rules of
// src/common/errors.hpp want it: with an hbt::InputError naming the file and the key at fault.
#pragma once
#include <gtest/gtest.h>

#include <string>

#include "common/errors.hpp"

namespace hbt::testing {

/// How expectInputError compares the error's key with the expected one.
enum class KeyMatch {
  kExact,     // key() == key
  kContains,  // key() contains key (a key the error qualifies, e.g. with a column or a prefix)
};

/// Runs f() and expects it to throw an hbt::InputError with file() == file and key() matching
/// key. Returns the error's message (what()) for further checks of its text; "" (and a test
/// failure) when f() returns normally. Any other exception propagates (gtest fails the test).
template <class F>
std::string expectInputError(F&& f, const std::string& file, const std::string& key,
                             KeyMatch match = KeyMatch::kExact) {
  try {
    f();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), file) << e.what();
    if (match == KeyMatch::kExact) {
      EXPECT_EQ(e.key(), key) << e.what();
    } else {
      EXPECT_NE(e.key().find(key), std::string::npos) << "key '" << e.key() << "' does not contain '"
                                                      << key << "': " << e.what();
    }
    return e.what();
  }
  ADD_FAILURE() << "no InputError (expected file '" << file << "', key '" << key << "')";
  return "";
}

}  // namespace hbt::testing
