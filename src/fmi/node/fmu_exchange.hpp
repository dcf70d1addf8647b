// The FMU participant's exchange of one communication step (fmu_participant.hpp), planned once
// before step 0 from the resolved mapping so that a step does only what it must:
//   inputs:  per input topic one lookup of the message held for the step (Input::at, the
//            lock-step's held-value rule), then its mapped fields read at their stored offsets,
//            converted field -> FMU unit (value_FMU = fmu.fromSi(field.toSi(v)), nothing when
//            the FMU declares the field's unit), into one vector per type;
//            one fmi2SetReal / fmi2SetInteger / fmi2SetBoolean over each vector;
//   outputs: one fmi2GetReal / fmi2GetInteger / fmi2GetBoolean over each type's value
//            references, converted FMU -> field unit (value_field = field.fromSi(fmu.toSi(v))),
//            written at their offsets into the messages the participant publishes next.
// The values are those of a field-by-field exchange, bit for bit (the same conversions in the
// same order; integers rounded with lround, booleans v != 0). Errors: a failing call names the
// FMU, the call, the variables of its batch and the time; a NaN output names the variable
// (Fmi2Instance); an array element beyond a message's length names the topic.
#pragma once
#include <ros/time.h>

#include <cstddef>
#include <vector>

#include "fmi/fmi2_instance.hpp"
#include "fmi/fmu_mapping.hpp"
#include "fmi/node/message_port.hpp"

namespace hbt::fmi {

class FmuExchange {
 public:
  /// map.inputs[i] is read from in_port_of[i], map.outputs[i] written to out_port_of[i];
  /// in_refs / out_refs: their variables as resolved by inst (settable / gettable).
  FmuExchange(const ResolvedMapping& map, const std::vector<InPort*>& in_port_of,
              const std::vector<OutPort*>& out_port_of, const std::vector<VariableRef>& in_refs,
              const std::vector<VariableRef>& out_refs, Fmi2Instance& inst);

  /// The inputs held for the step at t into the FMU.
  void setInputs(const ros::Time& t);
  /// The FMU's outputs into the messages; output(i) is map.outputs[i] as written [field units].
  void getOutputs();
  double output(std::size_t i) const { return out_values_[i]; }

 private:
  /// Where a value of one type goes or comes from: its index in that type's vector. `direct`:
  /// a Real in the field's own unit stored as a scalar double (the common case: every field of
  /// the twin's exported FMUs), copied at its offset without conversion or type switch.
  struct Entry {
    const Binding* binding = nullptr;
    FieldSlot slot;
    std::size_t index = 0;
    bool same_unit = true;  // Binding::sameUnit(): no conversion
    bool direct = false;
  };
  struct InputTopic {
    InPort* port = nullptr;
    std::vector<Entry> fields;
  };
  struct Typed {  // one type's batch and values
    VariableBatch batch;
    std::vector<double> reals;
    std::vector<int> integers;
    std::vector<fmi2Boolean> booleans;
  };
  struct Output {
    void* message = nullptr;  // OutPort::message(): the port's own message, at a fixed address
    Entry entry;
  };
  static Entry entry(const Binding& b, const FieldSlot& slot, std::size_t index);
  double inputValue(const void* msg, const Entry& e, const std::string& topic);
  double outputValue(const Entry& e) const;
  static Typed makeTyped(Fmi2Instance& inst, const std::vector<VariableRef>& refs, VarType t);
  void planInputs(const ResolvedMapping& map, const std::vector<InPort*>& in_port_of,
                  const std::vector<VariableRef>& in_refs);
  void planOutputs(const ResolvedMapping& map, const std::vector<OutPort*>& out_port_of,
                   const std::vector<VariableRef>& out_refs);
  static int typeIndex(VarType t);

  Fmi2Instance& inst_;
  std::vector<InputTopic> in_topics_;
  Typed in_[3], out_[3];  // by typeIndex: Real, Integer, Boolean
  std::vector<Output> outputs_;
  std::vector<double> out_values_;
};

}  // namespace hbt::fmi
