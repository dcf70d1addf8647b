"""What the live view (scripts/viz_node) draws and where: one frame of markers from the latest
message of every topic the run has (a gauge exists only when its topic does: a conventional
run has no battery, e-machine or EMS; thermal:=false has no cooling or aftertreatment;
hvac:=off no cabin).

Frame 'bus' (x along the road [m], z up): the bus at the origin on the road profile (+-300 m,
altitude relative to the bus, pitched with the gradient, brake lights when braking), the
mission's stops within 30 m behind to 70 m ahead (pole, sign, distance; the view's width), and
above the road in the plane y = 0 facing the camera of config/twin.rviz (x from -30 to 70 m):
  top     title; time, distance, next stop; the route strip: -200 m .. +800 m of the mission at
          1:10 with the bus and the stops (distance ahead written at each)
  left    dials: speed vs target [km/h], engine speed [rpm]; the gear (1..6, C converter, L locked);
          the EMS mode (hybrid)
  right   bars: engine torque vs its live full-load and motoring torque, e-machine crank torque vs
          its live limits, battery SOC, coolant, cabin (with "heater" while the fuel-fired heater
          burns, "A/C x kW" while the compressor runs), DOC / DPF / SCR bricks, battery cell,
          winding [degC]
  below   power flows [kW]: fuel -> engine -> wheels, battery <-> e-machine -> wheels,
          wheels -> friction brakes (arrow width ~ sqrt(power))
Wheel and brake power are the rates of the vehicle's cumulative wheel_work_j and
friction_brake_loss_j between the two last messages received.
"""
import bisect
import math

from geometry_msgs.msg import Point
from visualization_msgs.msg import Marker

from twin_tools.units import DIESEL_LHV_J_KG
from twin_tools.viz import markers as vm

K0 = 273.15
BUS = (0.15, 0.45, 0.95)       # bus body (the pixel test looks for this blue)
GREEN = (0.25, 0.85, 0.35)     # speed
ORANGE = (1.0, 0.55, 0.1)      # engine, fuel
RED = (0.95, 0.22, 0.18)       # temperatures, friction brakes
PURPLE = (0.7, 0.3, 0.95)      # e-machine
YELLOW = (0.95, 0.85, 0.15)    # battery
CYAN = (0.1, 0.8, 0.8)         # bus stops
COLD = (0.55, 0.75, 1.0)       # A/C
ROAD = (0.45, 0.45, 0.45)
# the power-flow diagram's component blocks: the hue of their gauges, darker (white labels)
DIM_ORANGE, DIM_RED, DIM_YELLOW, DIM_PURPLE = (0.5, 0.3, 0.08), (0.5, 0.12, 0.1), (0.5, 0.45, 0.08), (0.45, 0.2, 0.6)
EMS_MODES = {0: ("engine only", vm.GREY), 1: ("boost", PURPLE), 2: ("regen", GREEN),
             3: ("load-point shift", ORANGE), 4: ("electric / stop", YELLOW), 5: ("engine start", CYAN)}
GEARS = 6                      # config/vehicle.yaml gear_ratios (APT-S 6-speed)
ROAD_BEHIND_M, ROAD_AHEAD_M = 300.0, 300.0
STOPS_BEHIND_M, STOPS_AHEAD_M = 30.0, 70.0


class Road:
    """Altitude over distance (points every >= 5 m) and the stop positions of the mission."""

    def __init__(self, s_m=(), alt_m=(), stops_m=()):
        self.s, self.alt, self.stops = list(s_m), list(alt_m), sorted(stops_m)

    def altitude(self, d):
        if len(self.s) < 2:
            return self.alt[0] if self.alt else 0.0
        i = min(max(bisect.bisect_left(self.s, d), 1), len(self.s) - 1)
        w = vm.clip((d - self.s[i - 1]) / max(self.s[i] - self.s[i - 1], 1e-9), 0.0, 1.0)
        return self.alt[i - 1] + w * (self.alt[i] - self.alt[i - 1])

    def next_stop(self, d):
        """(index from 1, distance ahead [m]) of the first stop more than 5 m ahead, or None."""
        i = bisect.bisect_right(self.stops, d + 5.0)
        return (i + 1, self.stops[i] - d) if i < len(self.stops) else None


def _rot(x, z, pitch):
    c, s = math.cos(pitch), math.sin(pitch)
    return x * c - z * s, x * s + z * c


def draw_road_and_bus(sc, v, road):
    d = v.distance_m
    a0 = road.altitude(d)
    line = sc.add("road", Marker.LINE_STRIP, ROAD, scale=(0.6, 0.0, 0.0))
    lo = bisect.bisect_left(road.s, d - ROAD_BEHIND_M)
    hi = bisect.bisect_right(road.s, d + ROAD_AHEAD_M)
    line.points = [Point(x=s - d, y=0.0, z=a - a0) for s, a in zip(road.s[lo:hi], road.alt[lo:hi])]
    if len(line.points) < 2:   # no profile (yet): a flat road
        line.points = [Point(x=-ROAD_BEHIND_M, y=0.0, z=0.0), Point(x=ROAD_AHEAD_M, y=0.0, z=0.0)]
    pitch = math.atan(v.grade_percent / 100.0)
    q = (0.0, -math.sin(pitch / 2.0), 0.0, math.cos(pitch / 2.0))  # about -y: nose up on a climb

    def part(kind, color, x, z, size, y=0.0):
        px, pz = _rot(x, z, pitch)
        mk = sc.add("bus", kind, color, (px, y, pz), size)
        mk.pose.orientation.x, mk.pose.orientation.y, mk.pose.orientation.z, mk.pose.orientation.w = q
        return mk

    part(Marker.CUBE, BUS, 0.0, 1.9, (12.0, 2.55, 2.9))                       # body
    part(Marker.CUBE, (0.08, 0.1, 0.15), 0.3, 2.55, (10.6, 2.75, 1.0))         # window band
    for x in (-2.6, 3.6):                                                      # wheels
        w = part(Marker.CYLINDER, (0.3, 0.3, 0.3), x, 0.55, (1.1, 1.1, 2.9))
        w.pose.orientation.x, w.pose.orientation.w = math.sqrt(0.5), math.sqrt(0.5)  # axis along y
    lit = v.brake_pedal > 0.01 or v.friction_brake_applied_nm > 1.0
    for y in (-1.3, 1.3):          # brake lights, at the rear corners (seen from the side too)
        part(Marker.CUBE, (1.0, 0.05, 0.05) if lit else (0.3, 0.05, 0.05), -5.75, 1.2, (0.6, 0.12, 0.4), y)
    for i, s in enumerate(road.stops):
        ds = s - d
        if -STOPS_BEHIND_M <= ds <= STOPS_AHEAD_M:
            a = road.altitude(s) - a0
            sc.add("stops", Marker.CYLINDER, vm.GREY, (ds, -2.2, a + 1.6), (0.2, 0.2, 3.2))
            vm.box(sc, "stops", ds, a + 3.9, 1.8, 1.8, CYAN, "H", y=-2.2, label_h=1.4)
            vm.text(sc, "stops", ds, a + 6.6, "stop %d\n%.0f m" % (i + 1, ds), vm.TEXT_H)


def draw_header(sc, v, road, title):
    d = v.distance_m
    nxt = road.next_stop(d)
    stop = "next stop %d/%d in %.0f m" % (nxt[0], len(road.stops), nxt[1]) if nxt else "no stop ahead"
    vm.text(sc, "header", 20.0, 57.0, title, 2.4)
    vm.text(sc, "header", 20.0, 53.8, "t = %.1f s    s = %.3f km    %s" % (
        v.header.stamp.to_sec(), d / 1000.0, stop), 1.9, vm.GREY)
    # route strip: [d - 200 m, d + 800 m] at 1:10 on x = -30 .. 70 m
    z, x0 = 49.0, -10.0
    line = sc.add("route", Marker.LINE_STRIP, ROAD, scale=(0.35, 0.0, 0.0))
    line.points = [Point(x=-30.0, y=0.0, z=z), Point(x=70.0, y=0.0, z=z)]
    vm.box(sc, "route", x0, z, 1.6, 1.2, BUS, y=-0.2)
    vm.text(sc, "route", -33.5, z, "route", vm.TEXT_H * 0.8, vm.GREY)
    for i, s in enumerate(road.stops):
        ds = s - d
        if -200.0 <= ds <= 800.0:
            vm.box(sc, "route", x0 + ds / 10.0, z, 0.5, 2.0, CYAN, y=-0.1)
            if ds > 5.0:
                vm.text(sc, "route", x0 + ds / 10.0, z + 2.0, "%.0f m" % ds, vm.TEXT_H * 0.75)


def draw_dials(sc, st):
    v, e = st["vehicle"], st.get("engine")
    vm.dial(sc, "dials", -22.0, 36.0, 7.5, "speed", "km/h", v.speed_m_s * 3.6, 0.0, 90.0, GREEN,
            target=v.target_speed_m_s * 3.6)
    rpm = (e.engine_speed_rad_s if e else v.engine_speed_rad_s) * 30.0 / math.pi
    vm.dial(sc, "dials", -3.0, 36.0, 7.5, "engine", "rpm", rpm, 0.0, 2500.0, ORANGE)
    # gear: six squares, the engaged one lit; C = converter (lock-up open), L = locked
    for g in range(1, GEARS + 1):
        lit = g == v.gear
        x = -28.0 + 3.0 * (g - 1)
        vm.box(sc, "gear", x, 28.0, 2.5, 2.5, (0.92, 0.92, 0.92) if lit else vm.TRACK)
        vm.text(sc, "gear", x, 28.0, str(g), vm.TEXT_H, (0.1, 0.1, 0.1) if lit else vm.GREY, y=-0.3)
    state = "N" if v.gear == 0 else ("L" if v.converter_locked else "C")
    vm.text(sc, "gear", -4.0, 28.0, "gear %d %s" % (v.gear, state), vm.TEXT_H * 1.2)
    ems = st.get("ems")
    if ems is not None:
        name, color = EMS_MODES.get(ems.mode, ("mode %d" % ems.mode, vm.GREY))
        vm.box(sc, "ems", -28.0, 23.5, 2.5, 2.5, color)
        vm.text(sc, "ems", -14.0, 23.5, "EMS: %s%s" % (name, "" if ems.engine_on else ", engine off"),
                vm.TEXT_H * 1.1)


def draw_bars(sc, st):
    """The bar gauges of the topics present, left to right from x = 13 m, 5.4 m apart."""
    e, em, b, c, a = (st.get(k) for k in ("engine", "emachine", "battery", "cooling", "aftertreatment"))
    h = st.get("hvac")
    bars = []
    if e is not None:
        bars.append(("engine", "Nm", e.brake_torque_nm, -300.0, 1200.0, ORANGE,
                     [(e.torque_max_nm, vm.WHITE), (e.torque_min_nm, vm.WHITE)], "%.0f"))
    if em is not None:
        bars.append(("e-machine", "Nm", em.torque_nm, -900.0, 500.0, PURPLE,
                     [(em.torque_max_nm, vm.WHITE), (em.torque_min_nm, vm.WHITE)], "%.0f"))
    if b is not None:
        bars.append(("SOC", "%", 100.0 * b.soc, 0.0, 100.0, YELLOW, [], "%.1f"))
    if c is not None:
        bars.append(("coolant", "degC", c.coolant_ht_temperature_k - K0, 0.0, 120.0, RED, [], "%.0f"))
    if h is not None:
        bars.append(("cabin", "degC", h.cabin_temperature_k - K0, -10.0, 45.0, RED, [], "%.1f"))
    if a is not None:
        for name, t in (("DOC", a.doc_temperature_k), ("DPF", a.dpf_temperature_k), ("SCR", a.scr_temperature_k)):
            bars.append((name, "degC", t - K0, 0.0, 600.0, RED, [], "%.0f"))
    if b is not None:
        bars.append(("cell", "degC", b.cell_temperature_k - K0, 0.0, 60.0, RED, [], "%.1f"))
    if em is not None:
        bars.append(("winding", "degC", em.winding_temperature_k - K0, 0.0, 180.0, RED, [], "%.0f"))
    for i, (label, unit, value, lo, hi, color, marks, fmt) in enumerate(bars):
        vm.bar(sc, "bars", 13.0 + 5.4 * i, 31.0, label, unit, value, lo, hi, color, marks, fmt, height=11.0)
    if a is not None and a.light_off:
        i = [x[0] for x in bars].index("SCR")
        vm.text(sc, "bars", 13.0 + 5.4 * i, 45.0, "lit off", vm.TEXT_H * 0.8, GREEN)
    if h is not None and (h.aux_heater_on or h.compressor_power_w > 0.0):
        i = [x[0] for x in bars].index("cabin")
        what = "heater" if h.aux_heater_on else "A/C %.1f kW" % (h.compressor_power_w / 1e3)
        vm.text(sc, "bars", 13.0 + 5.4 * i, 45.0, what, vm.TEXT_H * 0.8, ORANGE if h.aux_heater_on else COLD)


def draw_flows(sc, st, p_wheel_w, p_brake_w):
    """Fuel -> engine -> wheels on the upper row, battery -> e-machine -> wheels on the lower,
    wheels -> brakes to the right; a box per component."""
    e, em = st.get("engine"), st.get("emachine")
    zt, zb, zw = 23.0, 13.0, 18.0
    vm.box(sc, "flows", 14.0, zt, 7.0, 3.0, DIM_ORANGE, "fuel")
    vm.box(sc, "flows", 30.0, zt, 7.0, 3.0, DIM_ORANGE, "engine")
    vm.box(sc, "flows", 48.0, zw, 7.0, 3.0, (0.2, 0.2, 0.2), "wheels")
    vm.box(sc, "flows", 65.0, zw, 7.0, 3.0, DIM_RED, "brakes")
    if e is not None:
        vm.flow(sc, "flows", (17.8, zt), (26.2, zt), e.fuel_mass_flow_kg_s * DIESEL_LHV_J_KG, ORANGE)
        vm.flow(sc, "flows", (33.8, zt - 0.5), (44.2, zw + 1.0), e.brake_torque_nm * e.engine_speed_rad_s,
                ORANGE, label_dx=0.0, label_dz=2.2)
    vm.flow(sc, "flows", (51.8, zw), (61.2, zw), p_brake_w, RED)
    vm.text(sc, "flows", 48.0, zw - 2.6, "hub %.1f kW" % (p_wheel_w / 1e3), vm.TEXT_H * 0.8, vm.GREY)
    if em is not None:
        vm.box(sc, "flows", 14.0, zb, 7.0, 3.0, DIM_YELLOW, "battery")
        vm.box(sc, "flows", 30.0, zb, 7.0, 3.0, DIM_PURPLE, "e-machine")
        vm.flow(sc, "flows", (17.8, zb), (26.2, zb), em.electrical_power_w, YELLOW)
        vm.flow(sc, "flows", (33.8, zb + 0.5), (44.2, zw - 1.0), em.torque_nm * em.speed_rad_s, PURPLE,
                label_dx=0.0, label_dz=-2.2)


def draw(sc, st, road, title, p_wheel_w, p_brake_w):
    """One frame: st = {'vehicle': VehicleState, 'engine': ..., ...} (latest of each topic)."""
    v = st["vehicle"]
    draw_road_and_bus(sc, v, road)
    draw_header(sc, v, road, title)
    draw_dials(sc, st)
    draw_bars(sc, st)
    draw_flows(sc, st, p_wheel_w, p_brake_w)
