#pragma once
// A small streaming JSON writer: enough for our result files, with correct commas,
// escaping, and non-finite numbers written as null.
#include <string>
#include <vector>

namespace swingsim {

class JsonWriter {
 public:
  JsonWriter& beginObject();
  JsonWriter& endObject();
  JsonWriter& beginArray();
  JsonWriter& endArray();
  /// Writes a key inside an object; the next call writes its value.
  JsonWriter& key(const std::string& k);
  JsonWriter& value(double v);
  JsonWriter& value(int v);
  JsonWriter& value(bool v);
  JsonWriter& value(const std::string& v);
  JsonWriter& value(const char* v) { return value(std::string(v)); }
  JsonWriter& value(const std::vector<double>& v);
  JsonWriter& value(const std::vector<bool>& v);
  JsonWriter& value(const std::vector<std::string>& v);
  JsonWriter& null();
  /// Shorthand: key(k).value(v).
  template <class T>
  JsonWriter& field(const std::string& k, const T& v) {
    key(k);
    return value(v);
  }
  const std::string& str() const { return out_; }

 private:
  void separate();
  std::string out_;
  std::vector<bool> first_;  // per open container: nothing written yet
  bool afterKey_ = false;
};

std::string jsonEscape(const std::string& s);

}  // namespace swingsim
