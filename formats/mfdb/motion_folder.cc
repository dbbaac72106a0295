#include "formats/mfdb/motion_folder.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <thread>

#include "formats/file_io.h"

namespace fs = std::filesystem;

namespace mocapfill {

namespace {

std::vector<std::string> Split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  std::string part;
  while (std::getline(stream, part, separator)) parts.push_back(part);
  return parts;
}

bool AllDigits(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c); });
}

// Label names listed one per line in <folder>/../cfg/<key>_label.txt (Bandai-Namco), with
// the data-set prefix ("dataset-1_") removed; empty when the file does not exist.
std::vector<std::string> LabelNames(const fs::path& clip_path, const std::string& key, const std::string& prefix) {
  std::ifstream in(clip_path.parent_path().parent_path() / "cfg" / (key + "_label.txt"));
  std::vector<std::string> names;
  std::string line;
  while (std::getline(in, line)) {
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
    if (!prefix.empty() && line.rfind(prefix, 0) == 0) line = line.substr(prefix.size());
    names.push_back(line);
  }
  return names;
}

Status AddJsonLabels(const fs::path& clip_path, const std::string& prefix, std::map<std::string, std::string>& labels) {
  fs::path json_path = clip_path;
  json_path.replace_extension(".json");
  std::error_code ec;
  if (!fs::is_regular_file(json_path, ec)) return OkStatus();
  ASSIGN_OR_RETURN(const std::string text, ReadFileBytes(json_path.string()));
  const nlohmann::json json = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (json.is_discarded() || !json.is_object())
    return InvalidData(json_path.string() + ": labels are not a JSON object");
  for (const auto& [key, value] : json.items()) {
    if (value.is_string()) {
      labels[key] = value.get<std::string>();
    } else if (value.is_number_integer()) {
      const long index = value.get<long>();
      labels[key + "_index"] = std::to_string(index);
      const std::vector<std::string> names = LabelNames(clip_path, key, prefix);
      if (index >= 0 && index < static_cast<long>(names.size())) labels[key] = names[index];
    } else if (value.is_number() || value.is_boolean()) {
      labels[key] = value.dump();
    }
  }
  return OkStatus();
}

}  // namespace

Result<std::map<std::string, std::string>> ReadClipLabels(const std::string& path) {
  const fs::path p(path);
  std::map<std::string, std::string> labels;
  labels["file"] = path;
  const std::string stem = p.stem().string();
  labels["name"] = stem;
  const std::vector<std::string> parts = Split(stem, '_');
  std::string prefix;
  if (parts.size() >= 4 && AllDigits(parts.back())) {
    labels["id"] = parts[parts.size() - 1];
    labels["style"] = parts[parts.size() - 2];
    labels["content"] = parts[parts.size() - 3];
    for (size_t i = 0; i + 3 < parts.size(); ++i) prefix += parts[i] + "_";
  }
  RETURN_IF_ERROR(AddJsonLabels(p, prefix, labels));
  return labels;
}

Result<std::vector<LabeledScene>> ImportMotionFiles(const std::vector<std::string>& files,
                                                    const ImportOptions& options, int threads,
                                                    const std::function<void()>& on_file_done) {
  const int count = static_cast<int>(files.size());
  std::vector<std::optional<Result<LabeledScene>>> results(count);
  std::atomic<int> next{0};
  auto work = [&] {
    for (int i = next.fetch_add(1); i < count; i = next.fetch_add(1)) {
      Result<Scene> scene = ImportFile(files[i], options);
      if (!scene.ok()) {
        results[i].emplace(scene.status());
      } else {
        Result<std::map<std::string, std::string>> labels = ReadClipLabels(files[i]);
        if (labels.ok()) {
          results[i].emplace(LabeledScene{std::move(scene).value(), std::move(labels).value()});
        } else {
          results[i].emplace(labels.status());
        }
      }
      if (on_file_done) on_file_done();
    }
  };
  const int workers =
      std::max(1, std::min(count, threads > 0 ? threads : static_cast<int>(std::thread::hardware_concurrency())));
  std::vector<std::thread> pool;
  for (int w = 1; w < workers; ++w) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  std::vector<LabeledScene> scenes;
  scenes.reserve(count);
  for (int i = 0; i < count; ++i) {
    if (!results[i]->ok()) return results[i]->status();
    scenes.push_back(std::move(*results[i]).value());
  }
  return scenes;
}

}  // namespace mocapfill
