#include "fmi/node/fmu_exchange.hpp"

#include <cmath>

namespace hbt::fmi {

int FmuExchange::typeIndex(VarType t) {
  switch (t) {
    case VarType::kReal: return 0;
    case VarType::kInteger:
    case VarType::kEnumeration: return 1;
    default: return 2;  // kBoolean (the mapping maps no other type)
  }
}

FmuExchange::Entry FmuExchange::entry(const Binding& b, const FieldSlot& slot, std::size_t index) {
  Entry e{&b, slot, index, b.sameUnit(), false};
  e.direct = b.type == VarType::kReal && e.same_unit && slot.store == Store::kDouble && slot.element < 0;
  return e;
}

FmuExchange::Typed FmuExchange::makeTyped(Fmi2Instance& inst, const std::vector<VariableRef>& refs, VarType t) {
  Typed ty;
  ty.batch = inst.batch(refs, t);
  ty.reals.resize(t == VarType::kReal ? refs.size() : 0);
  ty.integers.resize(t == VarType::kInteger ? refs.size() : 0);
  ty.booleans.resize(t == VarType::kBoolean ? refs.size() : 0);
  return ty;
}

FmuExchange::FmuExchange(const ResolvedMapping& map, const std::vector<InPort*>& in_port_of,
                         const std::vector<OutPort*>& out_port_of, const std::vector<VariableRef>& in_refs,
                         const std::vector<VariableRef>& out_refs, Fmi2Instance& inst)
    : inst_(inst) {
  planInputs(map, in_port_of, in_refs);
  planOutputs(map, out_port_of, out_refs);
}

void FmuExchange::planInputs(const ResolvedMapping& map, const std::vector<InPort*>& in_port_of,
                             const std::vector<VariableRef>& in_refs) {
  std::vector<VariableRef> refs[3];
  for (std::size_t i = 0; i < map.inputs.size(); ++i) {
    const Binding& b = map.inputs[i];
    const int ti = typeIndex(b.type);
    const Entry e = entry(b, in_port_of[i]->slot(b.field, b.element), refs[ti].size());
    refs[ti].push_back(in_refs[i]);
    std::size_t k = 0;  // the topic's group, in order of first appearance
    while (k < in_topics_.size() && in_topics_[k].port != in_port_of[i]) ++k;
    if (k == in_topics_.size()) in_topics_.push_back({in_port_of[i], {}});
    in_topics_[k].fields.push_back(e);
  }
  in_[0] = makeTyped(inst_, refs[0], VarType::kReal);
  in_[1] = makeTyped(inst_, refs[1], VarType::kInteger);
  in_[2] = makeTyped(inst_, refs[2], VarType::kBoolean);
}

void FmuExchange::planOutputs(const ResolvedMapping& map, const std::vector<OutPort*>& out_port_of,
                              const std::vector<VariableRef>& out_refs) {
  std::vector<VariableRef> refs[3];
  for (std::size_t i = 0; i < map.outputs.size(); ++i) {
    const Binding& b = map.outputs[i];
    const int ti = typeIndex(b.type);
    outputs_.push_back({out_port_of[i]->message(), entry(b, out_port_of[i]->slot(b.field, b.element), refs[ti].size())});
    refs[ti].push_back(out_refs[i]);
  }
  out_[0] = makeTyped(inst_, refs[0], VarType::kReal);
  out_[1] = makeTyped(inst_, refs[1], VarType::kInteger);
  out_[2] = makeTyped(inst_, refs[2], VarType::kBoolean);
  out_values_.assign(outputs_.size(), 0.0);
}

double FmuExchange::inputValue(const void* msg, const Entry& e, const std::string& topic) {
  const double v = readField(msg, e.slot, topic);
  switch (e.binding->type) {
    case VarType::kReal: return in_[0].reals[e.index] = e.same_unit ? v : e.binding->fmuFromField(v);
    case VarType::kInteger:
    case VarType::kEnumeration: return in_[1].integers[e.index] = static_cast<int>(std::lround(v));
    default: return in_[2].booleans[e.index] = v != 0.0 ? fmi2True : fmi2False;
  }
}

void FmuExchange::setInputs(const ros::Time& t) {
  double* reals = in_[0].reals.data();
  for (const InputTopic& topic : in_topics_) {
    const char* msg = static_cast<const char*>(topic.port->message(t));  // one lookup per topic
    for (const Entry& e : topic.fields) {
      if (e.direct) reals[e.index] = *reinterpret_cast<const double*>(msg + e.slot.offset);
      else inputValue(msg, e, topic.port->topic());
    }
  }
  inst_.setReals(in_[0].batch, in_[0].reals.data());
  inst_.setIntegers(in_[1].batch, in_[1].integers.data());
  inst_.setBooleans(in_[2].batch, in_[2].booleans.data());
}

double FmuExchange::outputValue(const Entry& e) const {
  switch (e.binding->type) {
    case VarType::kReal: return e.same_unit ? out_[0].reals[e.index] : e.binding->fieldFromFmu(out_[0].reals[e.index]);
    case VarType::kInteger:
    case VarType::kEnumeration: return out_[1].integers[e.index];
    default: return out_[2].booleans[e.index] != fmi2False ? 1.0 : 0.0;
  }
}

void FmuExchange::getOutputs() {
  inst_.getReals(out_[0].batch, out_[0].reals.data());
  inst_.getIntegers(out_[1].batch, out_[1].integers.data());
  inst_.getBooleans(out_[2].batch, out_[2].booleans.data());
  const double* reals = out_[0].reals.data();
  for (std::size_t i = 0; i < outputs_.size(); ++i) {
    const Output& o = outputs_[i];
    if (o.entry.direct) {
      out_values_[i] = *reinterpret_cast<double*>(static_cast<char*>(o.message) + o.entry.slot.offset) = reals[o.entry.index];
    } else {
      out_values_[i] = outputValue(o.entry);
      writeField(o.message, o.entry.slot, out_values_[i]);
    }
  }
}

}  // namespace hbt::fmi
