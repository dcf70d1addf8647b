// Shared check of a model's parameter binding for the model tests: a parameter source with one
// bad key (unknown, NaN, out of range, not an integer, inconsistent with another key) must be
// rejected with an InputError that names the source's file and that key.
#pragma once
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "common/params.hpp"
#include "input_errors.hpp"

namespace hbt::testing {

template <class P, class = void>
struct HasValidate : std::false_type {};
template <class P>
struct HasValidate<P, std::void_t<decltype(std::declval<const P&>().validate(std::string()))>>
    : std::true_type {};

/// Binds src to a fresh Params (keys under ignore_prefixes skipped, as a participant does for
/// cosim/), then, if Params has validate(file), validates it; expects the InputError naming
/// src.file and key. Returns the error's message.
template <class Params>
std::string expectRejected(const ParamSource& src, const std::string& key,
                           const std::vector<std::string>& ignore_prefixes = {}) {
  return expectInputError(
      [&] {
        Params q;
        ParamSet qs;
        q.declare(qs);
        applyParams(qs, src, ignore_prefixes);
        if constexpr (HasValidate<Params>::value) q.validate(src.file);
      },
      src.file, key);
}

}  // namespace hbt::testing
