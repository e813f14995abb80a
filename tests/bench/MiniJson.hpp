// A small strict JSON reader for the schema tests: objects, arrays, strings without
// escapes beyond \" \\ \n \r \t, numbers, true/false/null. Fails on anything else.
#pragma once

#include <cstdlib>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace minijson {

struct Value {
  enum Kind { Null, Bool, Number, String, Array, Object } kind = Null;
  bool b = false;
  double n = 0;
  std::string s;
  std::vector<Value> items;
  std::vector<std::pair<std::string, Value>> members;  // in file order

  const Value* get(const std::string& key) const {
    for (const auto& m : members)
      if (m.first == key) return &m.second;
    return nullptr;
  }
  std::vector<std::string> keys() const {
    std::vector<std::string> k;
    for (const auto& m : members) k.push_back(m.first);
    return k;
  }
};

class Parser {
 public:
  explicit Parser(const std::string& t) : _t(t) {}
  bool parse(Value* out) {
    if (!value(out)) return false;
    ws();
    return _i == _t.size();
  }

 private:
  void ws() {
    while (_i < _t.size() && (_t[_i] == ' ' || _t[_i] == '\n' || _t[_i] == '\r' || _t[_i] == '\t'))
      ++_i;
  }
  bool lit(const char* w) {
    const std::string s(w);
    if (_t.compare(_i, s.size(), s) != 0) return false;
    _i += s.size();
    return true;
  }
  bool str(std::string* out) {
    if (_t[_i] != '"') return false;
    ++_i;
    while (_i < _t.size() && _t[_i] != '"') {
      if (_t[_i] == '\\') {
        ++_i;
        if (_i >= _t.size()) return false;
        const char c = _t[_i];
        *out += c == 'n' ? '\n' : c == 'r' ? '\r' : c == 't' ? '\t' : c;
      } else {
        *out += _t[_i];
      }
      ++_i;
    }
    if (_i >= _t.size()) return false;
    ++_i;
    return true;
  }
  bool value(Value* v) {
    ws();
    if (_i >= _t.size()) return false;
    const char c = _t[_i];
    if (c == '{') {
      v->kind = Value::Object;
      ++_i;
      ws();
      if (_t[_i] == '}') return ++_i, true;
      for (;;) {
        ws();
        std::string key;
        if (!str(&key)) return false;
        ws();
        if (_t[_i] != ':') return false;
        ++_i;
        Value child;
        if (!value(&child)) return false;
        v->members.emplace_back(key, child);
        ws();
        if (_t[_i] == ',') {
          ++_i;
          continue;
        }
        if (_t[_i] == '}') return ++_i, true;
        return false;
      }
    }
    if (c == '[') {
      v->kind = Value::Array;
      ++_i;
      ws();
      if (_t[_i] == ']') return ++_i, true;
      for (;;) {
        Value child;
        if (!value(&child)) return false;
        v->items.push_back(child);
        ws();
        if (_t[_i] == ',') {
          ++_i;
          continue;
        }
        if (_t[_i] == ']') return ++_i, true;
        return false;
      }
    }
    if (c == '"') {
      v->kind = Value::String;
      return str(&v->s);
    }
    if (lit("null")) return v->kind = Value::Null, true;
    if (lit("true")) return v->kind = Value::Bool, v->b = true, true;
    if (lit("false")) return v->kind = Value::Bool, v->b = false, true;
    // JSON's number grammar first (strtod alone takes nan, inf, hex and a leading +):
    // -? (0 | [1-9][0-9]*) (. [0-9]+)? ([eE] [+-]? [0-9]+)?
    const size_t from = _i;
    size_t j = _i;
    auto digits = [&] {
      const size_t d = j;
      while (j < _t.size() && _t[j] >= '0' && _t[j] <= '9') ++j;
      return j > d;
    };
    if (j < _t.size() && _t[j] == '-') ++j;
    if (j < _t.size() && _t[j] == '0')
      ++j;
    else if (!digits())
      return false;
    if (j < _t.size() && _t[j] == '.') {
      ++j;
      if (!digits()) return false;
    }
    if (j < _t.size() && (_t[j] == 'e' || _t[j] == 'E')) {
      ++j;
      if (j < _t.size() && (_t[j] == '+' || _t[j] == '-')) ++j;
      if (!digits()) return false;
    }
    v->n = std::strtod(_t.substr(from, j - from).c_str(), nullptr);
    v->kind = Value::Number;
    _i = j;
    return true;
  }
  const std::string& _t;
  size_t _i = 0;
};

inline bool parse(const std::string& text, Value* out) {
  return Parser(text).parse(out);
}

}  // namespace minijson
