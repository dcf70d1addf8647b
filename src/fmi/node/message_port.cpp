#include "fmi/node/message_port.hpp"

#include <boost/make_shared.hpp>

#include <cmath>
#include <cstring>
#include <map>
#include <type_traits>
#include <vector>

#include "common/errors.hpp"
#include "fmi/node/fmu_participant.hpp"
#include "fmu_message_types.inc"  // generated from msg/ (src/fmi/node/CMakeLists.txt)

namespace hbt::fmi {
namespace {

/// How one field is stored in the C++ message.
enum class Store { kDouble, kFloat, kU8, kI8, kU16, kI16, kU32, kI32, kU64, kI64, kVecDouble, kOther };

struct Slot {
  Store store = Store::kOther;
  std::size_t offset = 0;
};

/// The Stream of Serializer<M>::allInOne: records the offset and storage of every field visited.
class SlotVisitor {
 public:
  explicit SlotVisitor(const void* base) : base_(static_cast<const char*>(base)) {}
  template <class T>
  void next(T& v) {
    record(v);
  }
  std::vector<Slot> slots;

 private:
  template <class A>
  void record(std_msgs::Header_<A>&) {}  // the header is not a field
  template <class C, class Tr, class A>
  void record(std::basic_string<C, Tr, A>& v) {
    add(Store::kOther, &v);
  }
  template <class T, class A>
  void record(std::vector<T, A>& v) {
    add(std::is_same<T, double>::value ? Store::kVecDouble : Store::kOther, &v);
  }
  template <class T>
  void record(T& v) {
    if constexpr (std::is_same<T, double>::value) add(Store::kDouble, &v);
    else if constexpr (std::is_same<T, float>::value) add(Store::kFloat, &v);
    else if constexpr (std::is_integral<T>::value) add(integer(sizeof(T), std::is_signed<T>::value), &v);
    else add(Store::kOther, &v);
  }
  static Store integer(std::size_t bytes, bool is_signed) {
    switch (bytes) {
      case 1: return is_signed ? Store::kI8 : Store::kU8;
      case 2: return is_signed ? Store::kI16 : Store::kU16;
      case 4: return is_signed ? Store::kI32 : Store::kU32;
      default: return is_signed ? Store::kI64 : Store::kU64;
    }
  }
  void add(Store s, const void* field) {
    slots.push_back({s, static_cast<std::size_t>(static_cast<const char*>(field) - base_)});
  }
  const char* base_;
};

bool compatible(FieldKind k, const std::string& type, Store s) {
  switch (k) {
    case FieldKind::kFloat64: return s == Store::kDouble;
    case FieldKind::kBool: return s == Store::kU8;
    case FieldKind::kFloat64Array: return s == Store::kVecDouble;
    case FieldKind::kInteger: {
      static const std::map<std::string, Store> want = {{"int8", Store::kI8},   {"uint8", Store::kU8},
                                                        {"int16", Store::kI16}, {"uint16", Store::kU16},
                                                        {"int32", Store::kI32}, {"uint32", Store::kU32},
                                                        {"int64", Store::kI64}, {"uint64", Store::kU64}};
      return want.at(type) == s;
    }
    default: return true;  // never read or written
  }
}

/// The layout and slots of M, checked against each other once.
template <class M>
struct TypeInfo {
  MessageLayout layout;
  std::vector<Slot> slots;
  static const TypeInfo& get() {
    static const TypeInfo info = make();
    return info;
  }
  static TypeInfo make() {
    TypeInfo t;
    const std::string datatype = ros::message_traits::datatype<M>();
    t.layout = MessageLayout::parse(datatype, ros::message_traits::definition<M>());
    M m;
    SlotVisitor v(&m);
    ros::serialization::Serializer<M>::template allInOne<SlotVisitor, M&>(v, m);
    t.slots = v.slots;
    const auto& f = t.layout.fields();
    if (!t.layout.hasHeader() || f.size() != t.slots.size())
      throw std::logic_error(datatype + ": definition and serialiser disagree (header, field count)");
    for (std::size_t i = 0; i < f.size(); ++i)
      if (!compatible(f[i].kind, f[i].type, t.slots[i].store))
        throw std::logic_error(datatype + ": field " + f[i].name + " is not stored as its definition says");
    return t;
  }
};

template <class T>
T& at(void* msg, const Slot& s) {
  return *reinterpret_cast<T*>(static_cast<char*>(msg) + s.offset);
}
template <class T>
const T& at(const void* msg, const Slot& s) {
  return *reinterpret_cast<const T*>(static_cast<const char*>(msg) + s.offset);
}

void write(void* msg, const Slot& s, int element, double v) {
  switch (s.store) {
    case Store::kDouble: at<double>(msg, s) = v; break;
    case Store::kU8: at<uint8_t>(msg, s) = static_cast<uint8_t>(std::lround(v)); break;
    case Store::kI8: at<int8_t>(msg, s) = static_cast<int8_t>(std::lround(v)); break;
    case Store::kU16: at<uint16_t>(msg, s) = static_cast<uint16_t>(std::lround(v)); break;
    case Store::kI16: at<int16_t>(msg, s) = static_cast<int16_t>(std::lround(v)); break;
    case Store::kU32: at<uint32_t>(msg, s) = static_cast<uint32_t>(std::llround(v)); break;
    case Store::kI32: at<int32_t>(msg, s) = static_cast<int32_t>(std::lround(v)); break;
    case Store::kU64: at<uint64_t>(msg, s) = static_cast<uint64_t>(std::llround(v)); break;
    case Store::kI64: at<int64_t>(msg, s) = static_cast<int64_t>(std::llround(v)); break;
    case Store::kVecDouble: at<std::vector<double>>(msg, s).at(static_cast<std::size_t>(element)) = v; break;
    default: throw std::logic_error("field not writable");
  }
}

double read(const void* msg, const Slot& s, int element, const std::string& topic) {
  switch (s.store) {
    case Store::kDouble: return at<double>(msg, s);
    case Store::kU8: return at<uint8_t>(msg, s);
    case Store::kI8: return at<int8_t>(msg, s);
    case Store::kU16: return at<uint16_t>(msg, s);
    case Store::kI16: return at<int16_t>(msg, s);
    case Store::kU32: return at<uint32_t>(msg, s);
    case Store::kI32: return at<int32_t>(msg, s);
    case Store::kU64: return static_cast<double>(at<uint64_t>(msg, s));
    case Store::kI64: return static_cast<double>(at<int64_t>(msg, s));
    case Store::kVecDouble: {
      const auto& vec = at<std::vector<double>>(msg, s);
      if (element < 0 || static_cast<std::size_t>(element) >= vec.size())
        throw ModelDivergence(topic, "element " + std::to_string(element),
                              "the message has " + std::to_string(vec.size()) + " elements");
      return vec[static_cast<std::size_t>(element)];
    }
    default: throw std::logic_error("field not readable");
  }
}

template <class M>
class TypedOut : public OutPort {
 public:
  explicit TypedOut(cosim::Output out) : out_(std::move(out)) {}
  const MessageLayout& layout() const override { return TypeInfo<M>::get().layout; }
  void set(std::size_t field, int element, double v) override { write(&msg_, TypeInfo<M>::get().slots.at(field), element, v); }
  void resize(std::size_t field, std::size_t n) override {
    at<std::vector<double>>(&msg_, TypeInfo<M>::get().slots.at(field)).resize(n);
  }
  void publish(const ros::Time& t) override {
    auto m = boost::make_shared<M>(msg_);
    m->header.stamp = t;
    out_.publish(m);
  }

 private:
  cosim::Output out_;
  M msg_;
};

template <class M>
class TypedIn : public InPort {
 public:
  explicit TypedIn(cosim::Input<M>& in) : in_(in) {}
  const MessageLayout& layout() const override { return TypeInfo<M>::get().layout; }
  double get(const ros::Time& t, std::size_t field, int element) const override {
    return read(&in_.at(t), TypeInfo<M>::get().slots.at(field), element, in_.topic());
  }

 private:
  cosim::Input<M>& in_;
};

struct Maker {
  const MessageLayout& (*layout)();
  std::unique_ptr<OutPort> (*output)(FmuParticipant&, const std::string&);
  std::unique_ptr<InPort> (*input)(FmuParticipant&, const std::string&);
};

template <class M>
Maker maker() {
  return {[]() -> const MessageLayout& { return TypeInfo<M>::get().layout; },
          [](FmuParticipant& p, const std::string& topic) -> std::unique_ptr<OutPort> {
            return std::make_unique<TypedOut<M>>(p.typedOutput<M>(topic));
          },
          [](FmuParticipant& p, const std::string& topic) -> std::unique_ptr<InPort> {
            return std::make_unique<TypedIn<M>>(p.typedInput<M>(topic));
          }};
}

const std::map<std::string, Maker>& makers() {
  namespace m = hybrid_bus_twin;
  static const std::map<std::string, Maker> kMakers = {
#define HBT_FMU_TYPE(M) {ros::message_traits::datatype<m::M>(), maker<m::M>()},
      HBT_FMU_MESSAGE_TYPES(HBT_FMU_TYPE)
#undef HBT_FMU_TYPE
  };
  return kMakers;
}

const Maker& makerOf(const std::string& datatype) {
  const auto it = makers().find(datatype);
  if (it == makers().end()) throw std::logic_error("unknown message type " + datatype);
  return it->second;
}

}  // namespace

bool PortFactory::known(const std::string& datatype) { return makers().count(datatype) > 0; }

MessageLayout PortFactory::layoutOf(const std::string& datatype, const std::string& where, const std::string& key) {
  if (!known(datatype))
    throw InputError(where, key, datatype + " is not a message type of this package (msg/*.msg)");
  return makerOf(datatype).layout();
}

std::unique_ptr<OutPort> PortFactory::output(const std::string& datatype, FmuParticipant& p, const std::string& topic) {
  return makerOf(datatype).output(p, topic);
}

std::unique_ptr<InPort> PortFactory::input(const std::string& datatype, FmuParticipant& p, const std::string& topic) {
  return makerOf(datatype).input(p, topic);
}

}  // namespace hbt::fmi
