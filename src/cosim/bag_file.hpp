// A rosbag (format 2.0, uncompressed) written sequentially: the file a rosbag::Bag opened for
// writing gives for the same write() calls, byte for byte (test_bag_file), without its cost.
//
// Why not rosbag::Bag: its write() seeks to the end of the file twice per message ("in case the
// previous operation was a read"). On a file opened for reading and writing every such fseeko
// flushes the stdio buffer and costs a write, an fstat, an lseek and a read system call: about
// 11 us per message on the development VM, 90 % of the bag thread's time for the ~730,000
// records of a full mission (perf of the nodelet manager during the map baseline). This writer
// keeps the file position itself, appends records to a buffer written out in blocks of
// kWriteBlock_bytes, and seeks only to fill in a finished chunk's sizes and, at close(), the file
// header -- the same fields rosbag fills in at the same moments.
//
// Layout (http://wiki.ros.org/Bags/Format/2.0; every integer little-endian; a record is
// <header length u32><header fields><data length u32><data>, a field <length u32>name=value):
//   "#ROSBAG V2.0\n", the file header record (index_pos u64, conn_count u32, chunk_count u32,
//   padded with spaces to kFileHeader_bytes), then chunks of at most a little over
//   kChunkThreshold_bytes: the chunk record (compression "none", size u32) holding the
//   connection records of connections first seen in it and the message data records (conn u32,
//   time = sec u32 nsec u32; the serialised message), each chunk followed by one index data
//   record per connection in it (ver 1, conn, count; data: time + offset u32 into the chunk per
//   message, in time order); at index_pos every connection record and one chunk info record per
//   chunk (ver 1, chunk_pos u64, start_time, end_time, count; data: conn + message count).
// A connection is a topic (its first message's type, md5sum and definition); ids in order of
// first appearance. Header fields are written in name order, as ros::Header writes a std::map.
//
// A process killed while writing leaves an unindexed bag (index_pos 0) that `rosbag reindex`
// repairs, as rosbag's own: the chunk in progress is in the file up to the last block written.
// Errors (cannot open, a failed write: disk full) throw std::runtime_error with the system's
// reason; after one, the file is left as it is and every later call throws again.
#pragma once
#include <ros/message_traits.h>
#include <ros/serialization.h>
#include <ros/time.h>

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace hbt::cosim {

class BagFileWriter {
 public:
  /// [B] A chunk is closed after the message that takes its data past this size (rosbag's
  /// default chunk threshold, so the chunks are the ones rosbag::Bag writes).
  static constexpr uint32_t kChunkThreshold_bytes = 768 * 1024;
  /// [B] The file header record's header + padding (rosbag's FILE_HEADER_LENGTH).
  static constexpr uint32_t kFileHeader_bytes = 4096;
  /// [B] Appended records are written to the file in blocks of this size (one write call each).
  static constexpr std::size_t kWriteBlock_bytes = 256 * 1024;

  /// Creates (truncates) `file` and writes the version line and the file header; throws
  /// std::runtime_error naming the file when it cannot.
  explicit BagFileWriter(const std::string& file);
  /// Closes the bag if close() was not called; an error there is dropped (call close() to see it).
  ~BagFileWriter();
  BagFileWriter(const BagFileWriter&) = delete;
  BagFileWriter& operator=(const BagFileWriter&) = delete;

  /// Appends `m` on `topic` at bag time `t` (any roscpp message or topic_tools::ShapeShifter).
  template <class M>
  void write(const std::string& topic, const ros::Time& t, const M& m) {
    const uint32_t conn = connection(topic, ros::message_traits::datatype(m), ros::message_traits::md5sum(m),
                                     ros::message_traits::definition(m), t);
    const uint32_t len = ros::serialization::serializationLength(m);
    uint8_t* data = beginMessage(conn, t, len);
    ros::serialization::OStream s(data, len);
    ros::serialization::serialize(s, m);
    endMessage(t);
  }
  /// Finishes the open chunk, writes the index and the file header, closes the file. Throws on a
  /// failed write; a second call does nothing.
  void close();
  /// Messages written so far.
  std::size_t messages() const { return messages_; }

 private:
  struct Connection {
    std::string topic;
    std::string fields;  // the connection header (md5sum, message_definition, type) as ros::Header writes it
    std::vector<std::pair<ros::Time, uint32_t>> chunk_index;  // this chunk's (time, offset into its data)
  };
  struct ChunkInfo {
    uint64_t pos = 0;  // [B] of the chunk record in the file
    ros::Time start, end;
    std::map<uint32_t, uint32_t> counts;  // connection -> messages in the chunk
  };

  /// The connection of `topic` (created on its first message; its record goes into the chunk
  /// that message opens or is in). Opens a chunk at t if none is open.
  uint32_t connection(const std::string& topic, const char* datatype, const char* md5sum,
                      const char* definition, const ros::Time& t);
  /// Appends the message data record's header and data length; returns where its `len` data bytes go.
  uint8_t* beginMessage(uint32_t conn, const ros::Time& t, uint32_t len);
  void endMessage(const ros::Time& t);
  void startChunk(const ros::Time& t);
  void stopChunk();
  void appendConnectionRecord(uint32_t id);
  /// The file header record (version 2.0 fields, padded to kFileHeader_bytes).
  std::string fileHeaderRecord(uint64_t index_pos) const;

  // --- the file: a logical offset, a buffer of appended bytes not yet written ---
  uint64_t offset() const { return flushed_ + buffer_.size(); }
  void append(const void* bytes, std::size_t n);
  void appendU32(uint32_t v) { append(&v, 4); }
  /// Appends a record header: the fields as (name, raw value bytes), already in name order.
  void appendHeader(std::initializer_list<std::pair<const char*, std::string>> fields);
  void flush();
  /// Overwrites `n` bytes at file offset `pos` (< offset()), in the buffer or in the file.
  void patch(uint64_t pos, const void* bytes, std::size_t n);
  [[noreturn]] void fail(const std::string& what);
  void checkOpen() const;

  std::string file_;
  int fd_ = -1;
  std::string error_;  // the first failure; every later call throws it
  std::vector<uint8_t> buffer_;
  uint64_t flushed_ = 0;  // [B] bytes written to the file

  std::map<std::string, uint32_t> topic_ids_;
  std::vector<Connection> connections_;  // by id
  std::vector<ChunkInfo> chunks_;
  bool chunk_open_ = false;
  ChunkInfo chunk_;
  uint64_t chunk_data_pos_ = 0;     // [B] file offset of the open chunk's data
  uint64_t chunk_size_field_ = 0;   // [B] file offset of its header's size value
  uint64_t chunk_data_len_pos_ = 0; // [B] file offset of its data length
  std::size_t messages_ = 0;
};

}  // namespace hbt::cosim
