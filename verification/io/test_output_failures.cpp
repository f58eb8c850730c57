// Claims: a failed write of the output is an OutputError (exit 5 in `ibms run`),
// not bad input: the message names the file and the system's reason, no temporary file is left,
// and an XDMF sidecar written before stays as it was. The failure is provoked without privileges by
// a file-size limit (RLIMIT_FSIZE, SIGXFSZ ignored): writes past it fail with EFBIG, as they would
// with ENOSPC on a full disk.
#define BOOST_TEST_MODULE output_failures
#include <boost/test/unit_test.hpp>

#include <sys/resource.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/errors.hpp"
#include "core/grid.hpp"
#include "io/csv_table.hpp"
#include "io/xdmf_sidecar.hpp"

namespace {

namespace fs = std::filesystem;

// Writes larger than `bytes` fail while this lives (soft limit; the hard limit is untouched).
struct FileSizeLimit {
  rlimit saved{};
  explicit FileSizeLimit(rlim_t bytes) {
    std::signal(SIGXFSZ, SIG_IGN);
    getrlimit(RLIMIT_FSIZE, &saved);
    rlimit limited = saved;
    limited.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &limited);
  }
  ~FileSizeLimit() { setrlimit(RLIMIT_FSIZE, &saved); }
};

const fs::path dir = fs::temp_directory_path() / ("ibms_output_failures_" + std::to_string(::getpid()));

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

BOOST_AUTO_TEST_CASE(failed_xdmf_write_is_an_output_error_and_leaves_no_temporary) {
  fs::create_directories(dir);
  const fs::path xmf = dir / "out.xmf";
  const ibms::Grid grid(64, 64, 1.0, 1.0);
  std::vector<ibms::XdmfSnapshot> snapshots;
  ibms::write_xdmf_sidecar(xmf.string(), "out.h5", grid, snapshots);  // a good sidecar first
  const std::string before = read(xmf);
  for (long step = 0; step < 50; ++step)
    snapshots.push_back({"/snapshots/" + std::to_string(100000 + step), 0.1 * step, {"u", "v", "p"}, {}});
  std::string message;
  {
    const FileSizeLimit limit(before.size() + 16);  // the longer sidecar cannot be written
    try {
      ibms::write_xdmf_sidecar(xmf.string(), "out.h5", grid, snapshots);
    } catch (const ibms::OutputError& e) {
      message = e.what();
    }
  }
  BOOST_TEST_MESSAGE(message);
  BOOST_TEST(message.find("out.xmf.tmp: cannot write XDMF sidecar: File too large") != std::string::npos, message);
  BOOST_TEST(!fs::exists(dir / "out.xmf.tmp"));
  BOOST_TEST(read(xmf) == before);  // the previous sidecar is intact
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(failed_csv_write_is_an_output_error_and_leaves_no_partial_table) {
  fs::create_directories(dir);
  const fs::path csv = dir / "out_bodies.csv";
  std::vector<double> column(2000, 1.0 / 3.0);
  std::string message;
  {
    const FileSizeLimit limit(4096);
    try {
      ibms::write_csv(csv.string(), {"test table"}, {"x [-]"}, {column});
    } catch (const ibms::OutputError& e) {
      message = e.what();
    }
  }
  BOOST_TEST_MESSAGE(message);
  BOOST_TEST(message.find("out_bodies.csv: cannot write CSV file: File too large") != std::string::npos, message);
  BOOST_TEST(!fs::exists(csv));
  fs::remove_all(dir);
}
