"""rqt_plot-style plot of numeric message fields from a bag of the twin, against header.stamp.

  scripts/twin plot DIR/run.bag /vehicle/state/speed_m_s /vehicle/state/target_speed_m_s [-o out.png]
                    [--from S] [--to S]
  (also scripts/plot_topic, e.g. rosrun hybrid_bus_twin plot_topic, with the same arguments)

Each argument is <topic>/<field>. Without -o the figure is written next to the bag as
plot_<field>.png (the machines running the twin are often headless).
"""
import argparse
import os
import sys

from twin_tools.bags.reader import BagError, open_bag


def main():
    ap = argparse.ArgumentParser(prog="plot_topic", description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("bag")
    ap.add_argument("series", nargs="+", help="<topic>/<field>")
    ap.add_argument("-o", "--out")
    ap.add_argument("--from", dest="t0", type=float, default=None)
    ap.add_argument("--to", dest="t1", type=float, default=None)
    a = ap.parse_args()
    wanted = {}
    for s in a.series:
        topic, _, field = s.rpartition("/")
        if not topic:
            sys.exit("plot_topic: '%s' is not <topic>/<field>" % s)
        wanted.setdefault(topic, []).append(field)
    data = {s: ([], []) for s in a.series}
    try:
        bag = open_bag(a.bag)
    except BagError as e:
        sys.exit("plot_topic: %s" % e)
    with bag:
        known = bag.get_type_and_topic_info().topics
        for t in wanted:
            if t not in known:
                sys.exit("plot_topic: topic %s not in %s (topics: %s)" % (t, a.bag, ", ".join(sorted(known))))
        for topic, msg, _ in bag.read_messages(topics=list(wanted)):
            ts = msg.header.stamp.to_sec()
            if (a.t0 is not None and ts < a.t0) or (a.t1 is not None and ts > a.t1):
                continue
            for f in wanted[topic]:
                if not hasattr(msg, f):
                    sys.exit("plot_topic: %s has no field '%s' (fields: %s)" % (topic, f, ", ".join(msg.__slots__)))
                data[topic + "/" + f][0].append(ts)
                data[topic + "/" + f][1].append(float(getattr(msg, f)))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(12, 4))
    for s, (t, v) in data.items():
        ax.plot(t, v, lw=0.8, label=s)
    ax.set_xlabel("time (header.stamp) [s]")
    ax.legend()
    ax.grid(alpha=0.3)
    out = a.out or os.path.join(os.path.dirname(os.path.abspath(a.bag)),
                                "plot_%s.png" % "_".join(s.rpartition("/")[2] for s in a.series))
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(out)


if __name__ == "__main__":
    main()
