#include "cosim/recorded_topic.hpp"

#include <topic_tools/shape_shifter.h>

#include <cstring>
#include <map>
#include <vector>

#include "recorded_types.inc"  // generated from msg/ (src/cosim/CMakeLists.txt)

namespace hbt::cosim {
namespace {

template <class M>
class TypedTopic : public RecordedTopic {
 public:
  explicit TypedTopic(Input<M>* in) : in_(in) {}
  InputBase* input() override { return in_; }
  /// header.seq is roscpp's per-publisher counter, filled in only when a message is serialised
  /// (TCP: mode nodes) and never for an intra-process subscriber (nodelets): written as 0, so
  /// both modes give the same bag.
  void write(AsyncBagWriter& bag, const ros::Time& bag_t, const ros::Time& t) const override {
    auto copy = std::make_shared<M>(in_->at(t));
    copy->header.seq = 0;
    bag.write(in_->topic(), bag_t, std::shared_ptr<const M>(std::move(copy)));
  }

 private:
  Input<M>* in_;
};

/// Type-erased input buffered by the header stamp read from the serialized message (every
/// message of the twin starts with std_msgs/Header: seq, stamp.sec, stamp.nsec).
class RawInput : public InputBase {
 public:
  using Ptr = topic_tools::ShapeShifter::ConstPtr;
  RawInput(ros::NodeHandle& nh, const std::string& topic, std::function<void()> cb, const std::string& subscribe_to)
      : InputBase(topic), resolved_(nh.resolveName(topic)), cb_(std::move(cb)) {
    const std::string source = subscribe_to.empty() ? topic : subscribe_to;
    local_ = LocalBus::topic(nh.resolveName(source));
    local_->addRosConsumer();  // served by roscpp: its producer in this process publishes through it
    sub_ = nh.subscribe<topic_tools::ShapeShifter>(source, 1000, &RawInput::callback, this,
                                                   ros::TransportHints().tcpNoDelay());
  }
  ~RawInput() override {
    sub_.shutdown();
    local_->removeRosConsumer();
  }
  bool has(const ros::Time& t) const override { return buf_.count(t) > 0; }
  const Ptr& at(const ros::Time& t) const { return buf_.at(heldStamp(t)); }
  void dropBefore(const ros::Time& t) override { buf_.erase(buf_.begin(), buf_.lower_bound(t)); }
  uint32_t numPublishers() const override { return sub_.getNumPublishers(); }
  std::string resolvedTopic() const override { return resolved_; }

 private:
  void callback(const Ptr& msg) {
    const uint32_t n = msg->size();
    if (n < 12) return;  // no header: not a twin message
    bytes_.resize(n);
    ros::serialization::OStream s(bytes_.data(), n);
    msg->write(s);
    uint32_t sec = 0, nsec = 0;
    std::memcpy(&sec, bytes_.data() + 4, 4);
    std::memcpy(&nsec, bytes_.data() + 8, 4);
    buf_[ros::Time(sec, nsec)] = msg;
    cb_();
  }
  std::string resolved_;
  std::shared_ptr<LocalTopic> local_;
  ros::Subscriber sub_;
  std::map<ros::Time, Ptr> buf_;
  std::vector<uint8_t> bytes_;
  std::function<void()> cb_;
};

class RawTopic : public RecordedTopic {
 public:
  explicit RawTopic(RawInput* in) : in_(in) {}
  InputBase* input() override { return in_; }
  void write(AsyncBagWriter& bag, const ros::Time& bag_t, const ros::Time& t) const override {
    bag.write(in_->topic(), bag_t, in_->at(t));  // the received message itself (immutable)
  }

 private:
  RawInput* in_;
};

template <class M>
std::unique_ptr<RecordedTopic> typed(ros::NodeHandle& nh, const std::string& topic, std::function<void()> cb,
                                     const std::string& subscribe_to, std::unique_ptr<InputBase>& input_out) {
  auto in = std::make_unique<Input<M>>(nh, topic, std::move(cb), subscribe_to);
  auto rec = std::make_unique<TypedTopic<M>>(in.get());
  input_out = std::move(in);
  return rec;
}

}  // namespace

std::unique_ptr<RecordedTopic> makeRecordedTopic(const std::string& datatype, ros::NodeHandle& nh,
                                                 const std::string& topic, std::function<void()> cb,
                                                 const std::string& subscribe_to,
                                                 std::unique_ptr<InputBase>& input_out) {
  namespace m = hybrid_bus_twin;
  using Maker = std::unique_ptr<RecordedTopic> (*)(ros::NodeHandle&, const std::string&, std::function<void()>,
                                                   const std::string&, std::unique_ptr<InputBase>&);
  static const std::map<std::string, Maker> makers = {
#define HBT_RECORDED_TYPE(M) {ros::message_traits::datatype<m::M>(), &typed<m::M>},
      HBT_RECORDED_TYPES(HBT_RECORDED_TYPE)
#undef HBT_RECORDED_TYPE
  };
  const auto it = makers.find(datatype);
  if (it != makers.end()) return it->second(nh, topic, std::move(cb), subscribe_to, input_out);
  auto in = std::make_unique<RawInput>(nh, topic, std::move(cb), subscribe_to);
  auto rec = std::make_unique<RawTopic>(in.get());
  input_out = std::move(in);
  return rec;
}

}  // namespace hbt::cosim
