// Output files appear whole or not at all: content goes to a temporary file beside the
// target, which is renamed over it only after a successful write.
#pragma once

#include <functional>
#include <string>
#include <string_view>

namespace tmu {

// Calls write(tmp_path) to produce the file, then renames tmp_path to `path`. On any
// exception the temporary is removed and `path` is left untouched.
void write_atomically(const std::string& path,
                      const std::function<void(const std::string&)>& write);

// Writes `bytes` to `path` atomically; throws InputError naming the path on failure.
void write_file_atomically(const std::string& path, std::string_view bytes);

}  // namespace tmu
