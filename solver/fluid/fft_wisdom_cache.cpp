// The FFTW wisdom cache (fft_wisdom_cache.hpp).
#include "fluid/fft_wisdom_cache.hpp"

#include <fftw3.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include "fluid/spectral_solver.hpp"

namespace ibms {

namespace {

// The wisdom text as this process last read or wrote it (what the cache file holds).
std::string& cached_text() {
  static std::string text;
  return text;
}

// Letters, digits, '.', '-' and '_' only: a library version or host name as part of a file name.
std::string file_name_part(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
                       c == '-' || c == '_';
    out.push_back(plain ? c : '_');
  }
  return out.empty() ? std::string("unknown") : out;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

std::string fft_wisdom_cache_path() {
  if (const char* set = std::getenv("IBMS_FFT_WISDOM"); set != nullptr) {
    const std::string value(set);
    return value == "off" ? std::string() : value;
  }
  std::filesystem::path folder;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg != nullptr && xdg[0] == '/') {
    folder = xdg;
  } else if (const char* home = std::getenv("HOME"); home != nullptr && home[0] == '/') {
    folder = std::filesystem::path(home) / ".cache";
  } else {
    return {};
  }
  char host[256] = {};
  if (gethostname(host, sizeof host - 1) != 0) host[0] = '\0';
  return (folder / "ibms" / ("fftw-wisdom-" + file_name_part(fftw_version) + "-" + file_name_part(host) + ".txt"))
      .string();
}

bool load_fft_wisdom_cache() {
  const std::string path = fft_wisdom_cache_path();
  if (path.empty()) return false;
  const std::string text = read_file(path);
  if (text.empty() || !import_fft_planner_wisdom(text)) return false;
  cached_text() = fft_planner_wisdom();  // as FFTW writes it back: unchanged unless it plans more
  return true;
}

bool save_fft_wisdom_cache() {
  const std::string path = fft_wisdom_cache_path();
  if (path.empty()) return false;
  if (fft_planner_wisdom() == cached_text()) return false;
  // What another run wrote since this one loaded the cache joins this run's plans (the plans
  // already made do not change), so that runs finishing one after another lose nothing.
  import_fft_planner_wisdom(read_file(path));
  const std::string text = fft_planner_wisdom();
  if (text.empty()) return false;
  std::error_code error;
  const std::filesystem::path target(path);
  if (target.has_parent_path()) std::filesystem::create_directories(target.parent_path(), error);
  const std::string part = path + ".part" + std::to_string(static_cast<long>(getpid()));
  {
    std::ofstream out(part, std::ios::binary | std::ios::trunc);
    if (!out) return false;
    out << text;
    out.close();
    if (!out) {
      std::remove(part.c_str());
      return false;
    }
  }
  std::filesystem::rename(part, target, error);  // atomic on one file system
  if (error) {
    std::remove(part.c_str());
    return false;
  }
  cached_text() = text;
  return true;
}

}  // namespace ibms
