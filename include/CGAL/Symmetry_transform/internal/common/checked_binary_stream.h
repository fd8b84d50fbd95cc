// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_CHECKED_BINARY_STREAM_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_CHECKED_BINARY_STREAM_H

// The frame of the package's binary files (the PRST, the symmetry descriptor):
//   8 bytes of signature (the kind of file), uint32 format version, uint32 byte-order mark
//   0x01020304, the payload, uint64 FNV-1a hash of all the bytes after the signature.
// Values are written in the machine's byte order; the mark makes a foreign order an error, the
// hash a corrupt or truncated file.

#include <cstdint>
#include <cstring>
#include <fstream>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>

namespace CGAL::Symmetry_transform::internal {

constexpr std::uint32_t byte_order_mark = 0x01020304;

class Fnv1a_hash
{
public:
  void add(const void* data, std::size_t size)
  {
    const unsigned char* bytes = static_cast<const unsigned char*>(data);
    for(std::size_t i = 0; i < size; ++i) hash_ = (hash_ ^ bytes[i]) * 1099511628211ull;
  }
  std::uint64_t value() const { return hash_; }

private:
  std::uint64_t hash_ = 14695981039346656037ull;
};

// A kind of file: its signature, its version, its name in the error messages, and the largest
// resolution n of the n^3 values of its payload (larger: a corrupt header).
struct Binary_format
{
  char signature[8];
  std::uint32_t version;
  const char* name;
  std::uint64_t max_resolution;
};

// Writes the head on construction, the payload by write(), the hash by finish(). The state of
// the stream tells whether the writing succeeded.
class Checked_binary_writer
{
public:
  Checked_binary_writer(std::ostream& os, const Binary_format& format) : os_(os)
  {
    os_.write(format.signature, sizeof(format.signature));
    write(&format.version, sizeof(format.version));
    write(&byte_order_mark, sizeof(byte_order_mark));
  }

  void write(const void* data, std::size_t size)
  {
    os_.write(static_cast<const char*>(data), std::streamsize(size));
    hash_.add(data, size);
  }

  void finish()
  {
    const std::uint64_t checksum = hash_.value();
    os_.write(reinterpret_cast<const char*>(&checksum), sizeof(checksum));
  }

private:
  std::ostream& os_;
  Fnv1a_hash hash_;
};

// Reads and checks the head on construction, the payload by read(), the hash by finish(); throws
// std::runtime_error, its message prefixed by `context`, on a foreign, truncated or corrupt file.
class Checked_binary_reader
{
public:
  Checked_binary_reader(std::istream& is, const Binary_format& format, std::string context)
    : is_(is), context_(std::move(context)), max_resolution_(format.max_resolution)
  {
    char signature[sizeof(format.signature)];
    if(!is_.read(signature, sizeof(signature)) || std::memcmp(signature, format.signature, sizeof(signature)) != 0)
      fail(std::string("not a ") + format.name + " file (bad signature)");
    std::uint32_t version = 0, mark = 0;
    read(&version, sizeof(version));
    if(version != format.version)
      fail("unsupported file format version " + std::to_string(version) + " (this library reads version " +
           std::to_string(format.version) + ")");
    read(&mark, sizeof(mark));
    if(mark != byte_order_mark) fail("the file was written with another byte order");
  }

  void read(void* data, std::size_t size)
  {
    if(!is_.read(static_cast<char*>(data), std::streamsize(size))) fail("the file is truncated");
    hash_.add(data, size);
  }

  // The resolution n of the n^3 values that follow, even and at most the format's maximum: a
  // guard against a corrupt header, checked before the values are allocated.
  std::size_t read_resolution()
  {
    std::uint64_t n = 0;
    read(&n, sizeof(n));
    if(n == 0 || n % 2 != 0 || n > max_resolution_) fail("corrupt header (resolution " + std::to_string(n) + ")");
    return std::size_t(n);
  }

  void finish()
  {
    std::uint64_t checksum = 0;
    if(!is_.read(reinterpret_cast<char*>(&checksum), sizeof(checksum))) fail("the file is truncated");
    if(checksum != hash_.value()) fail("the file is corrupt (checksum mismatch)");
  }

  [[noreturn]] void fail(const std::string& message) const { throw std::runtime_error(context_ + message); }

private:
  std::istream& is_;
  std::string context_;
  std::uint64_t max_resolution_;
  Fnv1a_hash hash_;
};

// write(os) into the file `filename`, created or overwritten; throws std::runtime_error, its
// message prefixed by `context`, if the file cannot be written.
template <typename Write>
void write_file(const std::string& filename, const std::string& context, const Write& write)
{
  std::ofstream os(filename, std::ios::binary);
  if(!os) throw std::runtime_error(context + ": cannot open " + filename + " for writing");
  write(os);
  if(!os) throw std::runtime_error(context + ": cannot write " + filename);
}

// read(is) of the file `filename`; throws std::runtime_error, its message prefixed by `context`,
// if the file cannot be opened.
template <typename Read>
auto read_file(const std::string& filename, const std::string& context, const Read& read)
{
  std::ifstream is(filename, std::ios::binary);
  if(!is) throw std::runtime_error(context + ": cannot open " + filename);
  return read(is);
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_CHECKED_BINARY_STREAM_H
