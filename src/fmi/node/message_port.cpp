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

using Slot = FieldSlot;

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

template <class M>
FieldSlot slotOf(std::size_t field, int element) {
  FieldSlot s = TypeInfo<M>::get().slots.at(field);
  s.element = element;
  return s;
}

template <class M>
class TypedOut : public OutPort {
 public:
  explicit TypedOut(cosim::Output out) : out_(std::move(out)) {}
  const MessageLayout& layout() const override { return TypeInfo<M>::get().layout; }
  void set(std::size_t field, int element, double v) override { writeField(&msg_, slot(field, element), v); }
  FieldSlot slot(std::size_t field, int element) const override { return slotOf<M>(field, element); }
  void* message() override { return &msg_; }
  void resize(std::size_t field, std::size_t n) override {
    detail::fieldAt<std::vector<double>>(&msg_, TypeInfo<M>::get().slots.at(field)).resize(n);
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
  FieldSlot slot(std::size_t field, int element) const override { return slotOf<M>(field, element); }
  const void* message(const ros::Time& t) const override { return &in_.at(t); }
  const std::string& topic() const override { return in_.topic(); }

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
