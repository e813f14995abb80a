#include "cuetrack/platform/fake/FakeSerial.hpp"

#include <cstdio>

namespace cuetrack::platform {

FakeSerialCable::FakeSerialCable() {
  _a._cable = this;
  _a._in = &_bToA;
  _a._out = &_aToB;
  std::snprintf(_a._name, sizeof _a._name, "fake-a");
  _b._cable = this;
  _b._in = &_aToB;
  _b._out = &_bToA;
  std::snprintf(_b._name, sizeof _b._name, "fake-b");
}

void FakeSerialCable::setPlugged(bool plugged) {
  _plugged = plugged;
  if (!plugged) {
    _aToB = End::Ring{};
    _bToA = End::Ring{};
  }
}

bool FakeSerialCable::End::reopen() {
  if (!_cable->_plugged) {
    std::snprintf(_error, sizeof _error, "%s: cannot open: unplugged", _name);
    return false;
  }
  _open = true;
  return true;
}

IoResult FakeSerialCable::End::read(uint8_t* buf, size_t cap, int /*timeoutMs*/) {
  if (!_open || !_cable->_plugged) {
    std::snprintf(_error, sizeof _error, "%s: read failed: peer gone", _name);
    _open = false;
    return {IoStatus::Closed, 0};
  }
  size_t n = 0;
  while (n < cap && _in->size > 0) {
    buf[n++] = _in->bytes[_in->head];
    _in->head = (_in->head + 1) % kRingBytes;
    --_in->size;
  }
  return {IoStatus::Ok, n};
}

bool FakeSerialCable::End::waitWritable(int /*timeoutMs*/) {
  if (!_open || !_cable->_plugged) return false;
  const size_t cap = (_out == &_cable->_aToB) ? _cable->_capAtoB : kRingBytes;
  return _out->size < cap;
}

IoResult FakeSerialCable::End::write(const uint8_t* data, size_t len) {
  if (!_open || !_cable->_plugged) {
    std::snprintf(_error, sizeof _error, "%s: write failed: peer gone", _name);
    _open = false;
    return {IoStatus::Closed, 0};
  }
  const size_t cap = (_out == &_cable->_aToB) ? _cable->_capAtoB : kRingBytes;
  if (_out->size >= cap) return {IoStatus::WouldBlock, 0};
  size_t n = 0;
  while (n < len && _out->size < cap) {
    _out->bytes[(_out->head + _out->size) % kRingBytes] = data[n++];
    ++_out->size;
  }
  return {IoStatus::Ok, n};
}

}  // namespace cuetrack::platform
