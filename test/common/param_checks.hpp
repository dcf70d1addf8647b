// Shared check of a model's parameter binding for the model tests: a parameter source with one
// bad key (unknown, NaN, out of range, not an integer) must be rejected with an InputError that
// names the source's file and that key.
#pragma once
#include <gtest/gtest.h>

#include <string>

#include "common/errors.hpp"
#include "common/params.hpp"

namespace hbt::testing {

template <class Params>
void expectRejected(const ParamSource& src, const std::string& key) {
  Params q;
  ParamSet qs;
  q.declare(qs);
  try {
    applyParams(qs, src);
    ADD_FAILURE() << "no InputError for " << key;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), src.file) << e.what();
    EXPECT_EQ(e.key(), key) << e.what();
  }
}

}  // namespace hbt::testing
