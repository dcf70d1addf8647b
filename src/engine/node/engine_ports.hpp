// The engine participant's topics: its closed-loop inputs from the thermal nodes and its three
// output messages filled from the model-neutral engine::EngineOutputs (SI, engine_model.hpp) by
// the conversion the FMU exports share (engine_interface/engine_io.hpp).
#pragma once
#include <hybrid_bus_twin/AftertreatmentState.h>
#include <boost/make_shared.hpp>
#include <hybrid_bus_twin/CoolingState.h>
#include <hybrid_bus_twin/EngineHeat.h>
#include <hybrid_bus_twin/EngineState.h>
#include <hybrid_bus_twin/ExhaustState.h>
#include <ros/ros.h>

#include "cosim/output.hpp"

#include "cosim/input_buffer.hpp"
#include "engine_interface/engine_io.hpp"

namespace hbt::engine {

/// The engine's closed loops with the thermal nodes: coolant and oil temperature from /cooling/state and
/// turbine-outlet back-pressure from /aftertreatment/state, each read (stamped t_k) only when the
/// scenario runs that participant. Without them 0 = none (the model's own defaults).
struct EngineLoopInputs {
  cosim::Input<hybrid_bus_twin::CoolingState>* cooling = nullptr;
  cosim::Input<hybrid_bus_twin::AftertreatmentState>* aftertreatment = nullptr;
  /// The cooling's state held for t; nullptr when the cooling does not run.
  const hybrid_bus_twin::CoolingState* coolingAt(const ros::Time& t) const {
    return cooling ? &cooling->at(t) : nullptr;
  }
  /// The aftertreatment's state held for t; nullptr when it does not run.
  const hybrid_bus_twin::AftertreatmentState* aftertreatmentAt(const ros::Time& t) const {
    return aftertreatment ? &aftertreatment->at(t) : nullptr;
  }
};

/// Publishers of /engine/state, /engine/exhaust, /engine/heat (advertised by the participant
/// through Participant::addOutput so that the step protocol knows them).
class EnginePorts {
 public:
  EnginePorts() = default;
  EnginePorts(cosim::Output state, cosim::Output exhaust, cosim::Output heat)
      : state_(std::move(state)), exhaust_(std::move(exhaust)), heat_(std::move(heat)) {}
  void publish(const ros::Time& t, const EngineOutputs& v) const {
    hybrid_bus_twin::EngineState s;
    s.header.stamp = t;
    writeEngineState(v, s);
    state_.publish(boost::make_shared<hybrid_bus_twin::EngineState>(s));
    hybrid_bus_twin::ExhaustState x;
    x.header.stamp = t;
    writeExhaustState(v, x);
    exhaust_.publish(boost::make_shared<hybrid_bus_twin::ExhaustState>(x));
    hybrid_bus_twin::EngineHeat h;
    h.header.stamp = t;
    writeEngineHeat(v, h);
    heat_.publish(boost::make_shared<hybrid_bus_twin::EngineHeat>(h));
  }

 private:
  cosim::Output state_, exhaust_, heat_;
};

}  // namespace hbt::engine
