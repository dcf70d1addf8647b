// No NaN travels on: every floating-point field of a participant's output is checked before it is
// published (Output::publish), so a model that yields NaN or inf stops the run at that step, naming
// the participant, the topic and field, and the time -- before any other participant or the bag
// sees the value. The walk uses the message's own generated serializer (its allInOne lists the
// fields in order) with a "stream" that only looks at the values: no copy, no allocation, about
// one comparison per field. Field names come from the message definition (message_traits).
#pragma once
#include <ros/message_traits.h>
#include <ros/serialization.h>

#include <boost/array.hpp>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace hbt::cosim {

/// Names of the top-level fields of a message definition, in order (constants and comments
/// skipped; the definitions of nested types after the first "===" line are not read).
std::vector<std::string> topLevelFieldNames(const std::string& definition);

namespace detail {
template <class T> struct IsSequence : std::false_type {};
template <class T, class A> struct IsSequence<std::vector<T, A>> : std::true_type {};
template <class T, std::size_t N> struct IsSequence<boost::array<T, N>> : std::true_type {};

/// The "stream" handed to Serializer<M>::write: records the first non-finite value.
class FiniteWalk {
 public:
  int bad_field = -1;       // top-level field index of the first non-finite value (-1: none)
  long bad_element = -1;    // its element if the field is an array
  double bad_value = 0.0;

  template <class T>
  void next(const T& v) {
    visit(v, -1);
    if (depth_ == 0) ++field_;
  }

 private:
  template <class T>
  void visit(const T& v, long element) {
    if constexpr (std::is_floating_point_v<T>) {
      if (!std::isfinite(v) && bad_field < 0) {
        bad_field = field_;
        bad_element = element;
        bad_value = static_cast<double>(v);
      }
    } else if constexpr (IsSequence<T>::value) {
      long i = 0;
      for (const auto& x : v) visit(x, depth_ == 0 ? i++ : element);
    } else if constexpr (ros::message_traits::IsMessage<T>::value) {
      ++depth_;
      ros::serialization::Serializer<T>::write(*this, v);
      --depth_;
    }
  }
  int field_ = 0, depth_ = 0;
};
}  // namespace detail

/// "" if every floating-point value of `m` is finite, else "field: value" (e.g. "soc: nan",
/// "cell_temperature_k[3]: inf") of the first one that is not.
template <class M>
std::string nonFiniteField(const M& m) {
  detail::FiniteWalk walk;
  ros::serialization::Serializer<M>::write(walk, m);
  if (walk.bad_field < 0) return "";
  static const std::vector<std::string> names =
      topLevelFieldNames(ros::message_traits::Definition<M>::value());
  std::ostringstream os;
  os << (static_cast<std::size_t>(walk.bad_field) < names.size() ? names[walk.bad_field]
                                                                  : "field " + std::to_string(walk.bad_field));
  if (walk.bad_element >= 0) os << "[" << walk.bad_element << "]";
  os << ": " << walk.bad_value;
  return os.str();
}

}  // namespace hbt::cosim
