"""One message appended to a closed, indexed bag (format 2.0): the run's metadata after a run.

rosbag.Bag(path, "a") first reads the whole index through Python objects (3-4 s for a full
mission's bag) to append one record. The index section of a bag is small and at its end: this
reads it as bytes, writes the new chunk where it began (the chunk holds the message, and the
connection record when the topic is new; then its index data record), writes the connection and
chunk info records again with the new ones, and fills in the file header -- the records rosbag
writes for the same append, so rosbag reads the result as it reads its own (test_bag_columns).
A bag without an index (cut short) raises columns.Unsupported: open it with rosbag, which says
how to repair it."""
import io
import struct

from twin_tools.bags.columns import (BAG_MAGIC, OP_CHUNK, OP_CHUNK_INFO, OP_CONNECTION, OP_FILE_HEADER,
                                     OP_INDEX_DATA, OP_MESSAGE, Unsupported, header_fields, read_record)

_FILE_HEADER_AT = len(BAG_MAGIC)


def _u32(v):
    return struct.pack("<I", v)


def _header(fields):
    """A record header (or a connection header): the fields in name order, each <len>name=value."""
    out = b""
    for name, value in sorted(fields):
        f = name.encode() + b"=" + value
        out += _u32(len(f)) + f
    return out


def _record(fields, data):
    h = _header(fields)
    return _u32(len(h)) + h + _u32(len(data)) + data


def append_at_end(path, topic, msg):
    """Appends msg (a genpy message) on topic to the bag at path, at the bag's end time (the
    latest message's; 1 ns in a bag without messages)."""
    with open(path, "r+b") as f:
        head = f.read(_FILE_HEADER_AT + 8 + 4096 + 64)
        if not head.startswith(BAG_MAGIC):
            raise Unsupported("not a format 2.0 bag")
        fh, _, _, _ = read_record(head, _FILE_HEADER_AT)
        index_pos = struct.unpack("<Q", fh["index_pos"])[0]
        n_conns, n_chunks = struct.unpack("<I", fh["conn_count"])[0], struct.unpack("<I", fh["chunk_count"])[0]
        if index_pos == 0:
            raise Unsupported("not indexed")
        if sorted(fh) != ["chunk_count", "conn_count", "index_pos", "op"]:
            raise Unsupported("file header fields %s" % sorted(fh))  # e.g. an encrypted bag
        f.seek(index_pos)
        tail = f.read()
        conns, pos = {}, 0
        for _ in range(n_conns):
            fields, start, n, pos = read_record(tail, pos)
            c = header_fields(tail, start, start + n)
            conns[fields["topic"].decode()] = (struct.unpack("<I", fields["conn"])[0], c["md5sum"])
        conn_records, chunk_infos = tail[:pos], tail[pos:]
        end_ns, pos = None, 0
        for _ in range(n_chunks):
            fields, _, _, pos = read_record(chunk_infos, pos)
            sec, nsec = struct.unpack("<II", fields["end_time"])
            end_ns = max(end_ns or 0, sec * 1000000000 + nsec)
        if pos != len(chunk_infos):
            raise Unsupported("unexpected records after the index")
        t = struct.pack("<II", *divmod(end_ns if end_ns is not None else 1, 1000000000))

        buf = io.BytesIO()
        msg.serialize(buf)
        known = conns.get(topic)
        new_conn = known is None or known[1] != msg._md5sum.encode()
        conn_id = n_conns if new_conn else known[0]
        conn_record = _record([("conn", _u32(conn_id)), ("op", bytes([OP_CONNECTION])), ("topic", topic.encode())],
                              _header([("topic", topic.encode()), ("type", msg._type.encode()),
                                       ("md5sum", msg._md5sum.encode()),
                                       ("message_definition", msg._full_text.encode())]))
        chunk_data = conn_record if new_conn else b""
        msg_offset = len(chunk_data)
        chunk_data += _record([("conn", _u32(conn_id)), ("op", bytes([OP_MESSAGE])), ("time", t)], buf.getvalue())
        chunk = _record([("compression", b"none"), ("op", bytes([OP_CHUNK])), ("size", _u32(len(chunk_data)))], chunk_data)
        index = _record([("conn", _u32(conn_id)), ("count", _u32(1)), ("op", bytes([OP_INDEX_DATA])), ("ver", _u32(1))],
                        t + _u32(msg_offset))
        info = _record([("chunk_pos", struct.pack("<Q", index_pos)), ("count", _u32(1)), ("end_time", t),
                        ("op", bytes([OP_CHUNK_INFO])), ("start_time", t), ("ver", _u32(1))], _u32(conn_id) + _u32(1))
        f.seek(index_pos)
        f.write(chunk + index + conn_records + (conn_record if new_conn else b"") + chunk_infos + info)
        f.truncate()
        # the file header: the new index position and counts (fixed-size fields: same length)
        fields = [("chunk_count", _u32(n_chunks + 1)), ("conn_count", _u32(n_conns + new_conn)),
                  ("index_pos", struct.pack("<Q", index_pos + len(chunk) + len(index))), ("op", bytes([OP_FILE_HEADER]))]
        f.seek(_FILE_HEADER_AT + 4)
        f.write(_header(fields))
