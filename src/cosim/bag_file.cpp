#include "cosim/bag_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace hbt::cosim {

namespace {

constexpr char kVersionLine[] = "#ROSBAG V2.0\n";
constexpr uint8_t kOpMessageData = 0x02, kOpFileHeader = 0x03, kOpIndexData = 0x04, kOpChunk = 0x05,
                  kOpChunkInfo = 0x06, kOpConnection = 0x07;
constexpr uint32_t kIndexVersion = 1, kChunkInfoVersion = 1;
constexpr uint32_t kIndexEntry_bytes = 12;      // time (sec, nsec) + offset, u32 each
constexpr uint32_t kChunkInfoEntry_bytes = 8;   // conn + count, u32 each

template <class T>
std::string raw(const T& v) {
  return std::string(reinterpret_cast<const char*>(&v), sizeof v);
}
std::string raw(const ros::Time& t) { return raw(t.sec) + raw(t.nsec); }
std::string op(uint8_t code) { return std::string(1, static_cast<char>(code)); }

/// A header block as ros::Header writes a std::map: the fields in name order, each <len>name=value.
std::string headerFields(const std::map<std::string, std::string>& fields) {
  std::string out;
  for (const auto& f : fields) {
    out += raw(static_cast<uint32_t>(f.first.size() + 1 + f.second.size()));
    out += f.first;
    out += '=';
    out += f.second;
  }
  return out;
}

}  // namespace

BagFileWriter::BagFileWriter(const std::string& file) : file_(file) {
  fd_ = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) throw std::runtime_error("cannot create " + file + ": " + std::strerror(errno));
  buffer_.reserve(kWriteBlock_bytes);
  append(kVersionLine, sizeof kVersionLine - 1);
  const std::string header = fileHeaderRecord(0);  // index_pos 0 until close(): unindexed, as rosbag's
  append(header.data(), header.size());
}

BagFileWriter::~BagFileWriter() {
  try {
    close();
  } catch (...) {  // a destructor must not throw: close() is the place to see the error
  }
  if (fd_ >= 0) ::close(fd_);
}

std::string BagFileWriter::fileHeaderRecord(uint64_t index_pos) const {
  const uint32_t conns = static_cast<uint32_t>(connections_.size());
  const uint32_t chunks = static_cast<uint32_t>(chunks_.size());
  const std::string fields = headerFields(
      {{"chunk_count", raw(chunks)}, {"conn_count", raw(conns)}, {"index_pos", raw(index_pos)}, {"op", op(kOpFileHeader)}});
  const uint32_t len = static_cast<uint32_t>(fields.size());
  const uint32_t pad = len < kFileHeader_bytes ? kFileHeader_bytes - len : 0;
  return raw(len) + fields + raw(pad) + std::string(pad, ' ');
}

void BagFileWriter::appendHeader(std::initializer_list<std::pair<const char*, std::string>> fields) {
  uint32_t len = 0;
  for (const auto& f : fields) len += 4 + static_cast<uint32_t>(std::strlen(f.first)) + 1 + f.second.size();
  appendU32(len);
  for (const auto& f : fields) {
    const uint32_t n = static_cast<uint32_t>(std::strlen(f.first));
    appendU32(n + 1 + static_cast<uint32_t>(f.second.size()));
    append(f.first, n);
    append("=", 1);
    append(f.second.data(), f.second.size());
  }
}

uint32_t BagFileWriter::connection(const std::string& topic, const char* datatype, const char* md5sum,
                                   const char* definition, const ros::Time& t) {
  checkOpen();
  if (!chunk_open_) startChunk(t);
  const auto it = topic_ids_.find(topic);
  if (it != topic_ids_.end()) return it->second;
  const uint32_t id = static_cast<uint32_t>(connections_.size());
  Connection c;
  c.topic = topic;
  c.fields = headerFields({{"md5sum", md5sum}, {"message_definition", definition}, {"type", datatype}});
  connections_.push_back(std::move(c));
  topic_ids_.emplace(topic, id);
  appendConnectionRecord(id);  // in the chunk of its first message
  return id;
}

void BagFileWriter::appendConnectionRecord(uint32_t id) {
  const Connection& c = connections_[id];
  appendHeader({{"conn", raw(id)}, {"op", op(kOpConnection)}, {"topic", c.topic}});
  appendU32(static_cast<uint32_t>(c.fields.size()));
  append(c.fields.data(), c.fields.size());
}

void BagFileWriter::startChunk(const ros::Time& t) {
  chunk_ = ChunkInfo();
  chunk_.pos = offset();
  chunk_.start = chunk_.end = t;
  // the sizes are filled in by stopChunk(); their offsets follow from the fields' fixed lengths
  const uint32_t zero = 0;
  appendHeader({{"compression", "none"}, {"op", op(kOpChunk)}, {"size", raw(zero)}});
  chunk_size_field_ = offset() - 4;
  chunk_data_len_pos_ = offset();
  appendU32(0);
  chunk_data_pos_ = offset();
  chunk_open_ = true;
}

uint8_t* BagFileWriter::beginMessage(uint32_t conn, const ros::Time& t, uint32_t len) {
  connections_[conn].chunk_index.emplace_back(t, static_cast<uint32_t>(offset() - chunk_data_pos_));
  ++chunk_.counts[conn];
  appendHeader({{"conn", raw(conn)}, {"op", op(kOpMessageData)}, {"time", raw(t)}});
  appendU32(len);
  if (buffer_.size() + len > buffer_.capacity()) flush();
  const std::size_t at = buffer_.size();
  buffer_.resize(at + len);  // a message larger than the block grows the buffer once
  return buffer_.data() + at;
}

void BagFileWriter::endMessage(const ros::Time& t) {
  ++messages_;
  if (t > chunk_.end) chunk_.end = t;
  else if (t < chunk_.start) chunk_.start = t;
  if (offset() - chunk_data_pos_ > kChunkThreshold_bytes) stopChunk();
}

void BagFileWriter::stopChunk() {
  const uint32_t size = static_cast<uint32_t>(offset() - chunk_data_pos_);
  patch(chunk_size_field_, &size, 4);     // uncompressed size
  patch(chunk_data_len_pos_, &size, 4);   // stored size (the same: no compression)
  for (uint32_t id = 0; id < connections_.size(); ++id) {  // index data records, by connection id
    auto& index = connections_[id].chunk_index;
    if (index.empty()) continue;
    std::stable_sort(index.begin(), index.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    const uint32_t count = static_cast<uint32_t>(index.size());
    appendHeader({{"conn", raw(id)}, {"count", raw(count)}, {"op", op(kOpIndexData)}, {"ver", raw(kIndexVersion)}});
    appendU32(count * kIndexEntry_bytes);
    for (const auto& e : index) {
      appendU32(e.first.sec);
      appendU32(e.first.nsec);
      appendU32(e.second);
    }
    index.clear();
  }
  chunks_.push_back(chunk_);
  chunk_open_ = false;
}

void BagFileWriter::close() {
  if (fd_ < 0) return;
  checkOpen();
  if (chunk_open_) stopChunk();
  const uint64_t index_pos = offset();
  for (uint32_t id = 0; id < connections_.size(); ++id) appendConnectionRecord(id);
  for (const ChunkInfo& c : chunks_) {
    const uint32_t count = static_cast<uint32_t>(c.counts.size());
    appendHeader({{"chunk_pos", raw(c.pos)}, {"count", raw(count)}, {"end_time", raw(c.end)},
                  {"op", op(kOpChunkInfo)}, {"start_time", raw(c.start)}, {"ver", raw(kChunkInfoVersion)}});
    appendU32(count * kChunkInfoEntry_bytes);
    for (const auto& kv : c.counts) {
      appendU32(kv.first);
      appendU32(kv.second);
    }
  }
  flush();
  // the file header again, now with the index position and the counts (same length: fixed-size fields)
  const std::string header = fileHeaderRecord(index_pos);
  patch(sizeof kVersionLine - 1, header.data(), header.size());
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) fail("close failed");
}

void BagFileWriter::append(const void* bytes, std::size_t n) {
  if (buffer_.size() + n > buffer_.capacity()) flush();
  const auto* b = static_cast<const uint8_t*>(bytes);
  buffer_.insert(buffer_.end(), b, b + n);
}

void BagFileWriter::flush() {
  std::size_t done = 0;
  while (done < buffer_.size()) {
    const ssize_t n = ::write(fd_, buffer_.data() + done, buffer_.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail("write failed");
    done += static_cast<std::size_t>(n);
  }
  flushed_ += done;
  buffer_.clear();
  if (buffer_.capacity() > kWriteBlock_bytes) {  // after a message larger than the block
    std::vector<uint8_t>().swap(buffer_);
    buffer_.reserve(kWriteBlock_bytes);
  }
}

void BagFileWriter::patch(uint64_t pos, const void* bytes, std::size_t n) {
  if (pos >= flushed_) {  // still in the buffer
    std::memcpy(buffer_.data() + (pos - flushed_), bytes, n);
    return;
  }
  if (pos + n > flushed_) flush();  // straddles the buffer's start: write it out first
  std::size_t done = 0;
  while (done < n) {
    const ssize_t w = ::pwrite(fd_, static_cast<const uint8_t*>(bytes) + done, n - done,
                               static_cast<off_t>(pos + done));
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) fail("write failed");
    done += static_cast<std::size_t>(w);
  }
}

void BagFileWriter::fail(const std::string& what) {
  const int e = errno;
  error_ = what + ": " + std::strerror(e);
  throw std::runtime_error(error_);
}

void BagFileWriter::checkOpen() const {
  if (!error_.empty()) throw std::runtime_error(error_);
  if (fd_ < 0) throw std::runtime_error("the bag " + file_ + " is closed");
}

}  // namespace hbt::cosim
