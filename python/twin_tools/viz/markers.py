"""Drawing primitives of the live view (scripts/viz_node): rviz markers in frame 'bus'
(x along the road [m], y across, z up) collected into one MarkerArray per frame.

Gauges are flat shapes in the vertical plane y = 0 facing the default camera of
config/twin.rviz (which looks along +y): positions are (x, z) pairs in metres of that plane.
  Scene           collects markers with stable ids per namespace and deletes the ones that
                  disappeared since the last frame
  bar()           vertical bar gauge: track, fill from zero (or the low end), limit marks,
                  label and unit below, value above
  dial()          semicircular dial: grey arc, coloured arc up to the value, a target needle
  flow()          power-flow arrow between two points, shaft width ~ sqrt(|power|), reversed
                  when the power is negative, labelled in kW
  box()/text()    labelled blocks and text
"""
import math

from geometry_msgs.msg import Point
from std_msgs.msg import ColorRGBA
from visualization_msgs.msg import Marker, MarkerArray

FRAME = "bus"
WHITE = (1.0, 1.0, 1.0)
GREY = (0.55, 0.55, 0.55)
TRACK = (0.22, 0.22, 0.22)   # unfilled part of a gauge (unsaturated: never taken for a gauge colour)
TEXT_H = 1.6                 # height of gauge labels [m]


def rgba(c, a=1.0):
    return ColorRGBA(r=c[0], g=c[1], b=c[2], a=a)


class Scene:
    """The markers of one frame. ids count per namespace in drawing order, so an element keeps
    its id from frame to frame; finish() adds DELETE for ids drawn last frame but not now."""

    def __init__(self):
        self.markers = []
        self.count = {}

    def add(self, ns, kind, color=WHITE, pos=(0.0, 0.0, 0.0), scale=(1.0, 1.0, 1.0)):
        mk = Marker()
        mk.header.frame_id = FRAME
        mk.ns = ns
        mk.id = self.count.get(ns, 0)
        self.count[ns] = mk.id + 1
        mk.type = kind
        mk.action = Marker.ADD
        mk.pose.position.x, mk.pose.position.y, mk.pose.position.z = pos
        mk.pose.orientation.w = 1.0
        mk.scale.x, mk.scale.y, mk.scale.z = scale
        mk.color = rgba(color)
        self.markers.append(mk)
        return mk

    def finish(self, previous):
        """MarkerArray of this frame; `previous` = {ns: count} of the last frame (updated)."""
        arr = MarkerArray(markers=list(self.markers))
        for ns, n in previous.items():
            for mid in range(self.count.get(ns, 0), n):
                mk = Marker()
                mk.header.frame_id = FRAME
                mk.ns, mk.id, mk.action = ns, mid, Marker.DELETE
                arr.markers.append(mk)
        previous.clear()
        previous.update(self.count)
        return arr


def text(sc, ns, x, z, s, height=TEXT_H, color=WHITE, y=0.0):
    mk = sc.add(ns, Marker.TEXT_VIEW_FACING, color, (x, y, z), (1.0, 1.0, height))
    mk.text = s
    return mk


def box(sc, ns, x, z, w, h, color, label=None, y=0.0, depth=0.2, label_h=TEXT_H):
    """Flat block centred at (x, z), w x h [m]; the label is written on it."""
    sc.add(ns, Marker.CUBE, color, (x, y, z), (w, depth, h))
    if label:
        text(sc, ns, x, z, label, label_h, WHITE, y - depth / 2 - 0.6)  # in front: not cut by the box


def clip(v, lo, hi):
    return min(max(v, lo), hi)


def bar(sc, ns, x, z0, label, unit, value, lo, hi, color, marks=(), fmt="%.0f", height=11.0, width=2.4):
    """Vertical bar gauge with its base at z0, spanning lo..hi; filled from 0 when lo < 0 < hi,
    else from lo. marks: (value, colour) lines across the bar (limits, targets)."""
    span = hi - lo

    def zof(v):
        return z0 + height * (clip(v, lo, hi) - lo) / span

    box(sc, ns, x, z0 + height / 2, width, height, TRACK, depth=0.1, y=0.1)
    if value is not None and math.isfinite(value):
        base = zof(0.0) if lo < 0.0 < hi else z0
        top = zof(value)
        if abs(top - base) > 1e-3:
            box(sc, ns, x, (base + top) / 2, width, abs(top - base), color, depth=0.2)
        text(sc, ns, x, z0 + height + 1.3, fmt % value, TEXT_H)
    for v, c in marks:
        if v is not None and math.isfinite(v):
            box(sc, ns, x, zof(v), width + 0.8, 0.3, c, depth=0.3, y=-0.1)
    text(sc, ns, x, z0 - 1.2, label, TEXT_H * 0.85, GREY)
    text(sc, ns, x, z0 - 2.8, unit, TEXT_H * 0.75, GREY)


def _arc(sc, ns, cx, cz, r_in, r_out, a0, a1, color, y=0.0, n=24):
    """Annulus sector from angle a0 to a1 [rad] (0 = right, counter-clockwise) as triangles in
    the plane at y (the fill in front of the track: no z-fighting)."""
    mk = sc.add(ns, Marker.TRIANGLE_LIST, color)
    for i in range(n):
        t0 = a0 + (a1 - a0) * i / n
        t1 = a0 + (a1 - a0) * (i + 1) / n
        p = [Point(x=cx + r * math.cos(t), y=y, z=cz + r * math.sin(t))
             for r, t in ((r_in, t0), (r_out, t0), (r_out, t1), (r_in, t1))]
        mk.points += [p[0], p[1], p[2], p[0], p[2], p[3]]
    return mk


def dial(sc, ns, cx, cz, r, label, unit, value, lo, hi, color, target=None, fmt="%.0f"):
    """Semicircular dial centred at (cx, cz), lo at the left end and hi at the right end; the
    value as a coloured arc, the target (if any) as a white needle; value and unit inside."""
    def ang(v):
        return math.pi * (1.0 - (clip(v, lo, hi) - lo) / (hi - lo))

    _arc(sc, ns, cx, cz, 0.7 * r, r, 0.0, math.pi, TRACK, y=0.1)
    if value is not None and math.isfinite(value) and value > lo:
        _arc(sc, ns, cx, cz, 0.7 * r, r, ang(value), math.pi, color, y=-0.1)
    if target is not None and math.isfinite(target):
        a = ang(target)
        mk = sc.add(ns, Marker.LINE_LIST, WHITE, scale=(0.45, 0.0, 0.0))
        mk.points = [Point(x=cx + 0.55 * r * math.cos(a), y=-0.2, z=cz + 0.55 * r * math.sin(a)),
                     Point(x=cx + 1.08 * r * math.cos(a), y=-0.2, z=cz + 1.08 * r * math.sin(a))]
        text(sc, ns, cx, cz + 0.3 * r - 2.2, "target " + fmt % target, TEXT_H * 0.75, GREY)
    text(sc, ns, cx, cz + 0.3 * r, (fmt % value) if value is not None else "-", TEXT_H * 1.5)
    text(sc, ns, cx, cz - 2.0, "%s [%s]" % (label, unit), TEXT_H * 0.85, GREY)
    for v in (lo, hi):
        a = ang(v)
        text(sc, ns, cx + 0.85 * r * math.cos(a), cz - 0.8, fmt % v, TEXT_H * 0.7, GREY)


P_REF_W = 300e3   # power that draws the widest arrow shaft, 1.6 m (width ~ sqrt(|P| / P_REF_W))
P_MIN_W = 200.0   # below this no arrow, only the label


def flow(sc, ns, a, b, power_w, color, label_dx=0.0, label_dz=1.8):
    """Arrow from point a=(x, z) to b for power_w > 0 (b to a when negative), shaft width
    growing with sqrt(|power|); the value in kW written next to its middle."""
    if power_w is None or not math.isfinite(power_w):
        return
    if abs(power_w) >= P_MIN_W:
        p0, p1 = (a, b) if power_w > 0 else (b, a)
        w = 0.2 + 1.4 * math.sqrt(min(abs(power_w) / P_REF_W, 1.0))
        mk = sc.add(ns, Marker.ARROW, color, scale=(w, w * 1.8, 1.0 + w))
        mk.points = [Point(x=p0[0], y=0.0, z=p0[1]), Point(x=p1[0], y=0.0, z=p1[1])]
    text(sc, ns, (a[0] + b[0]) / 2 + label_dx, (a[1] + b[1]) / 2 + label_dz,
         "%.1f kW" % (power_w / 1e3), TEXT_H * 0.85)
