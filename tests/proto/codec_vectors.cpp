// Test tool for the independent DBC cross-check (dbc_crosscheck.py, python3-canmatrix):
//   codec_vectors encode classic|fd SEED COUNT  -> JSON lines: frames encoded by tread's codec from
//                                                  random physical values, with tread's decoding
//   codec_vectors decode classic|fd FILE        -> JSON lines: tread's decoding and E2E verdict of
//                                                  each "ID#HEX" / "ID##FHEX" line of FILE
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>

#include "dbc/dbc_writer.hpp"
#include "proto/codec.hpp"
#include "proto/e2e_profile1.hpp"
#include "proto/role_table.hpp"

namespace {

using namespace tread;

std::string hex(const proto::CanFrame& f) {
  std::string out;
  char b[3];
  for (std::size_t i = 0; i < f.len; ++i) {
    std::snprintf(b, sizeof(b), "%02X", f.data[i]);
    out += b;
  }
  return out;
}

void print_values(const proto::MessageSpec& m, const proto::CanFrame& f) {
  const std::span<const std::uint8_t> bytes(f.data.data(), f.len);
  std::cout << "\"values\":{";
  bool first = true;
  for (const proto::SignalSpec& s : m.signals) {
    std::cout << (first ? "" : ",") << '"' << host::signal_name(s) << "\":";
    first = false;
    // Integer signals exactly; physical ones as tread's float decoding.
    if (proto::is_integer_role(s.role)) {
      std::cout << proto::decode_raw_signal(s, bytes);
    } else {
      char b[40];
      std::snprintf(b, sizeof(b), "%.9g", static_cast<double>(proto::decode_signal(s, bytes)));
      std::cout << b;
    }
  }
  std::cout << '}';
}

int encode_random(proto::Layout layout, unsigned seed, int count) {
  std::mt19937 rng(seed);
  for (int n = 0; n < count; ++n) {
    for (const proto::MessageSpec& m : proto::messages(layout)) {
      proto::CanFrame frame{};
      frame.id = m.id;
      frame.len = m.len;
      frame.fd = m.fd;
      const std::span<std::uint8_t> bytes(frame.data.data(), frame.len);
      // Random value per signal, within (and sometimes beyond) its range: the codec saturates.
      for (const proto::SignalSpec& s : m.signals) {
        if (s.role == proto::Role::crc || s.role == proto::Role::counter) {
          continue;
        }
        if (proto::is_integer_role(s.role)) {
          std::uniform_int_distribution<std::int64_t> d(s.raw_min(), s.raw_max());
          static_cast<void>(proto::encode_raw_signal(s, d(rng), bytes));
        } else {
          const double span = s.physical_max() - s.physical_min();
          std::uniform_real_distribution<double> d(s.physical_min() - 0.05 * span,
                                                   s.physical_max() + 0.05 * span);
          static_cast<void>(proto::encode_signal(s, static_cast<float>(d(rng)), bytes));
        }
      }
      proto::e2e_protect(frame, m.data_id(), static_cast<std::uint8_t>(n % 15));
      std::cout << "{\"message\":\"" << host::message_name(m) << "\",\"id\":" << m.id
                << ",\"fd\":" << (m.fd ? "true" : "false") << ",\"data\":\"" << hex(frame) << "\",";
      print_values(m, frame);
      std::cout << "}\n";
    }
  }
  return 0;
}

int decode_file(proto::Layout layout, const char* path) {
  std::ifstream in(path);
  if (!in) {
    std::cerr << "codec_vectors: cannot open " << path << '\n';
    return 2;
  }
  std::string line;
  int line_no = 0;
  proto::E2eReceiver receivers[proto::kMaxMessages]{};
  while (std::getline(in, line)) {
    ++line_no;
    const auto hash = line.find('#');
    if (hash == std::string::npos) {
      std::cerr << path << ':' << line_no << ": expected ID#DATA\n";
      return 2;
    }
    proto::CanFrame f{};
    f.id = static_cast<std::uint32_t>(std::stoul(line.substr(0, hash), nullptr, 16));
    std::string data = line.substr(hash + 1);
    if (!data.empty() && data[0] == '#') {
      f.fd = true;
      data = data.substr(2);  // "##<flags>"
    }
    f.len = static_cast<std::uint8_t>(data.size() / 2);
    for (std::size_t i = 0; i < f.len; ++i) {
      f.data[i] = static_cast<std::uint8_t>(std::stoul(data.substr(2 * i, 2), nullptr, 16));
    }
    const proto::MessageSpec* m = proto::find_message(layout, f.id);
    if (m == nullptr) {
      std::cerr << path << ':' << line_no << ": unknown id\n";
      return 2;
    }
    const auto e2e = proto::e2e_check(f, m->data_id(), receivers[proto::message_index(layout, *m)]);
    std::cout << "{\"message\":\"" << host::message_name(*m)
              << "\",\"e2e_ok\":" << (proto::e2e_accepted(e2e) ? "true" : "false") << ',';
    print_values(*m, f);
    std::cout << "}\n";
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5 && argc != 4) {
    std::cerr << "usage: codec_vectors encode classic|fd SEED COUNT | decode classic|fd FILE\n";
    return 2;
  }
  const std::string mode = argv[1];
  const proto::Layout layout =
      std::string(argv[2]) == "fd" ? proto::Layout::fd : proto::Layout::classic;
  if (mode == "encode" && argc == 5) {
    return encode_random(layout, static_cast<unsigned>(std::atoi(argv[3])), std::atoi(argv[4]));
  }
  if (mode == "decode" && argc == 4) {
    return decode_file(layout, argv[3]);
  }
  std::cerr << "codec_vectors: bad arguments\n";
  return 2;
}
