"""A run's bag as columns: {topic: {field: numpy array}}, read straight from the file.

rosbag's Python reader builds a Python object per record (header dict, rospy.Time, message): about
40 us per message, 30 s for the ~780,000 records of a full mission, most of a report's time. The
twin's bags are uncompressed format 2.0 (http://wiki.ros.org/Bags/Format/2.0; written by
src/cosim/bag_file.hpp or rosbag itself), and every message of a state topic has the same layout:
a std_msgs/Header and fixed-size fields. So this reader walks the chunks once with `struct` (the
message records' header fields at their fixed places), keeps each message's data offset, and
gathers each numeric field of a topic with one numpy operation over all its messages.

What it returns is what a loop over `rosbag.Bag.read_messages()` gives (test_bag_columns checks
it array for array on every message type of the package): per topic, in the bag's time order,
't' = header.stamp [s] (secs + nsecs / 1e9, as rospy's to_sec()) and every top-level field whose
value is a bool, int or float, as float64. A topic whose layout varies between messages (strings
or arrays of changing length) is decoded message by message with the class generated from the
bag's own message definition, as rosbag does. A bag this reader does not handle (compressed
chunks, not indexed, not format 2.0) raises Unsupported: the caller reads it with rosbag, which
also names what is wrong with a broken file."""
import struct

import numpy as np

BAG_MAGIC = b"#ROSBAG V2.0\n"
# the record op codes of format 2.0 (every record's "op" field, one byte)
OP_MESSAGE, OP_FILE_HEADER, OP_INDEX_DATA, OP_CHUNK, OP_CHUNK_INFO, OP_CONNECTION = 2, 3, 4, 5, 6, 7
# A message data record as rosbag writes it: the header fields in name order (conn, op, time) at
# fixed places, then the data length: <hlen 38><9>conn=<u32><4>op=<0x02><13>time=<sec><nsec><len>.
_MSG_RECORD = struct.Struct("<I9sI7sB9sIII")
_MSG_TAGS = (38, b"\x09\x00\x00\x00conn=", b"\x04\x00\x00\x00op=", OP_MESSAGE, b"\x0d\x00\x00\x00time=")

# ROS primitive types: numpy dtype (little-endian)
_PRIMITIVES = {"bool": "u1", "int8": "i1", "byte": "i1", "uint8": "u1", "char": "u1", "int16": "<i2",
               "uint16": "<u2", "int32": "<i4", "uint32": "<u4", "int64": "<i8", "uint64": "<u8",
               "float32": "<f4", "float64": "<f8"}
_FIXED_SIZE = {"time": 8, "duration": 8}
_U32 = struct.Struct("<I")


class Unsupported(Exception):
    """A bag (or part of one) this reader does not handle: read it with rosbag instead."""


def header_fields(buf, pos, end):
    out = {}
    while pos < end:
        (n,) = _U32.unpack_from(buf, pos)
        name, _, value = buf[pos + 4:pos + 4 + n].partition(b"=")
        out[name.decode()] = value
        pos += 4 + n
    return out


def read_record(buf, pos):
    """(header fields, data start, data length, next record) of the record at pos."""
    (hlen,) = _U32.unpack_from(buf, pos)
    fields = header_fields(buf, pos + 4, pos + 4 + hlen)
    (dlen,) = _U32.unpack_from(buf, pos + 4 + hlen)
    start = pos + 8 + hlen
    return fields, start, dlen, start + dlen


def _u32(fields, name):
    return _U32.unpack(fields[name])[0]


def _index(buf):
    """Connections {id: (topic, type, definition)} and the message records per connection as
    arrays (bag time [ns], data offset, data length) in the file's order."""
    if buf[:len(BAG_MAGIC)] != BAG_MAGIC:
        raise Unsupported("not a format 2.0 bag")
    head, _, _, _ = read_record(buf, len(BAG_MAGIC))
    if head.get("op") != bytes([OP_FILE_HEADER]):
        raise Unsupported("no file header")
    index_pos = struct.unpack("<Q", head["index_pos"])[0]
    if index_pos == 0:
        raise Unsupported("not indexed")
    conns, chunks, pos = {}, [], index_pos
    for _ in range(_u32(head, "conn_count")):
        f, start, dlen, pos = read_record(buf, pos)
        if f.get("op") != bytes([OP_CONNECTION]):
            raise Unsupported("connection record expected")
        c = header_fields(buf, start, start + dlen)
        conns[_u32(f, "conn")] = (f["topic"].decode(), c["type"].decode(), c["message_definition"].decode())
    for _ in range(_u32(head, "chunk_count")):
        f, _, _, pos = read_record(buf, pos)
        if f.get("op") != bytes([OP_CHUNK_INFO]):
            raise Unsupported("chunk info record expected")
        chunks.append(struct.unpack("<Q", f["chunk_pos"])[0])
    records = {c: ([], [], []) for c in conns}
    for chunk_pos in sorted(chunks):
        f, start, dlen, _ = read_record(buf, chunk_pos)
        if f.get("op") != bytes([OP_CHUNK]) or f.get("compression") != b"none":
            raise Unsupported("compressed chunk")
        pos, end = start, start + dlen
        while pos < end:
            h = _MSG_RECORD.unpack_from(buf, pos) if pos + _MSG_RECORD.size <= end else None
            if h is not None and (h[0], h[1], h[3], h[4], h[5]) == _MSG_TAGS:
                r = records[h[2]]
                r[0].append(h[6] * 1000000000 + h[7])
                r[1].append(pos + _MSG_RECORD.size)
                r[2].append(h[8])
                pos += _MSG_RECORD.size + h[8]
                continue
            f, start_r, n, nxt = read_record(buf, pos)
            if f.get("op") == bytes([OP_MESSAGE]):  # fields in another order: still a message
                r = records[_u32(f, "conn")]
                sec, nsec = struct.unpack("<II", f["time"])
                r[0].append(sec * 1000000000 + nsec)
                r[1].append(start_r)
                r[2].append(n)
            pos = nxt
    out = {}
    for c, (t, off, n) in records.items():
        t, off, n = np.asarray(t, np.int64), np.asarray(off, np.int64), np.asarray(n, np.int64)
        order = np.argsort(t, kind="stable")  # rosbag reads a connection in bag-time order
        out[c] = (off[order], n[order])
    return conns, out


def _message_class(datatype, definition):
    import genpy.dynamic
    return genpy.dynamic.generate_dynamic(datatype, definition)[datatype]


def _layout(cls, first):
    """Offsets of `cls`'s top-level slots in the serialised message `first` (bytes), with the
    offsets of every length prefix on the way (strings, arrays: equal in all messages = one
    layout). None where it cannot be walked (arrays of messages)."""
    lengths, slots = [], {}

    def walk(c, pos, top):
        for name, typ in zip(c.__slots__, c._slot_types):
            start = pos
            base, is_array, count = _array_of(typ)
            if is_array and count is None:
                lengths.append(pos)
                (count,) = _U32.unpack_from(first, pos)
                pos += 4
            elem = _PRIMITIVES.get(base)
            if base == "string":
                for _ in range(count if is_array else 1):
                    lengths.append(pos)
                    (n,) = _U32.unpack_from(first, pos)
                    pos += 4 + n
            elif elem is not None or base in _FIXED_SIZE:
                size = np.dtype(elem).itemsize if elem else _FIXED_SIZE[base]
                pos += size * (count if is_array else 1)
            elif is_array:
                return None  # an array of messages
            else:
                sub = _slot_class(c, name)
                pos = walk(sub, pos, False)
                if pos is None:
                    return None
            if top:
                slots[name] = (typ, start)
        return pos

    end = walk(cls, 0, True)
    if end is None or end != len(first):
        return None
    return slots, lengths


def _array_of(typ):
    if not typ.endswith("]"):
        return typ, False, None
    base, _, n = typ[:-1].partition("[")
    return base, True, (int(n) if n else None)


def _slot_class(cls, name):
    return type(getattr(cls(), name))


def _numeric_slots(cls):
    """The top-level slots read_run keeps (value a bool, int or float): the numeric primitives."""
    return [n for n, t in zip(cls.__slots__, cls._slot_types) if t in _PRIMITIVES]


def _columns_fixed(buf, off, cls, layout, first):
    slots, lengths = layout
    size = len(first)
    rows = b"".join([buf[o:o + size] for o in off.tolist()])  # every message's bytes, one after the other
    names, formats, offsets = [], [], []
    for i, at in enumerate(lengths):  # the length prefixes: equal to the first's = one layout
        names.append("len%d" % i), formats.append("<u4"), offsets.append(at)
    hdr_at = slots["header"][1]
    names += ["sec", "nsec"]
    formats += ["<u4", "<u4"]
    offsets += [hdr_at + 4, hdr_at + 8]  # std_msgs/Header: seq, stamp (secs, nsecs), frame_id
    numeric = _numeric_slots(cls)
    for name in numeric:
        typ, at = slots[name]
        names.append("f_" + name), formats.append(_PRIMITIVES[typ]), offsets.append(at)
    rec = np.frombuffer(rows, np.dtype({"names": names, "formats": formats, "offsets": offsets, "itemsize": size}))
    for i, at in enumerate(lengths):
        if not np.all(rec["len%d" % i] == _U32.unpack_from(first, at)[0]):
            return None
    cols = {"t": rec["sec"].astype(np.float64) + rec["nsec"].astype(np.float64) / 1e9}
    for name in numeric:
        raw = rec["f_" + name]
        cols[name] = (raw != 0).astype(np.float64) if slots[name][0] == "bool" else raw.astype(np.float64)
    return cols


def _columns_each(buf, off, n, cls):
    """Message by message (a layout that varies): as read_run's loop over rosbag's messages."""
    fields = None
    cols = None
    for o, k in zip(off.tolist(), n.tolist()):
        m = cls()
        m.deserialize(buf[o:o + k])
        if fields is None:
            fields = [f for f in m.__slots__ if isinstance(getattr(m, f), (bool, int, float))]
            cols = {f: [] for f in ["t"] + fields}
        cols["t"].append(m.header.stamp.to_sec())
        for f in fields:
            cols[f].append(float(getattr(m, f)))
    return {f: np.asarray(v) for f, v in cols.items()}


def read_columns(path, messages_of=()):
    """({topic: {field: array}}, {topic: [message, ...]}) of the bag at path: columns of every
    topic with a std_msgs/Header, and the messages themselves of the topics in `messages_of`
    (e.g. the run's JSON metadata). Raises Unsupported for a bag to be read with rosbag."""
    with open(path, "rb") as f:
        buf = f.read()  # ~200 MB for a full mission: one copy, far less than rosbag's objects
    try:
        conns, records = _index(buf)
    except (struct.error, KeyError, IndexError) as e:
        raise Unsupported("malformed: %s" % e)
    columns, messages = {}, {}
    for c, (topic, datatype, definition) in sorted(conns.items(), key=lambda kv: kv[0]):
        off, n = records[c]
        if len(off) == 0:
            continue
        cls = _message_class(datatype, definition)
        if topic in messages_of:
            out = []
            for o, k in zip(off.tolist(), n.tolist()):
                m = cls()
                m.deserialize(buf[o:o + k])
                out.append(m)
            messages[topic] = messages.get(topic, []) + out
            continue
        if "header" not in cls.__slots__ or cls._slot_types[cls.__slots__.index("header")] != "std_msgs/Header":
            continue
        if topic in columns:  # one topic on several connections: not the twin's bags
            raise Unsupported("topic %s on several connections" % topic)
        first = buf[off[0]:off[0] + n[0]]
        layout = _layout(cls, first) if np.all(n == n[0]) else None
        cols = _columns_fixed(buf, off, cls, layout, first) if layout else None
        columns[topic] = cols if cols is not None else _columns_each(buf, off, n, cls)
    return columns, messages
