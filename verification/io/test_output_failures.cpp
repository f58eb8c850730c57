// Claims: a failed write of the output is an OutputError (exit 5 in `ibms run`), not bad input,
// wherever it happens: in the XDMF sidecar, a CSV table, an HDF5 flush, or an HDF5 dataset write
// itself (a dataset larger than HDF5's 64 kB sieve buffer goes to the file inside H5Dwrite). The
// message names the file, what was written and the system's reason on one line; no temporary file
// is left, and an XDMF sidecar written before stays as it was. The failure is provoked without
// privileges by a file-size limit (RLIMIT_FSIZE, SIGXFSZ ignored): writes past it fail with EFBIG,
// as they would with ENOSPC on a full disk.
#define BOOST_TEST_MODULE output_failures
#include <boost/test/unit_test.hpp>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "core/grid.hpp"
#include "io/csv_table.hpp"
#include "io/output_file.hpp"
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

// Runs `body` in a child process and returns the text it returned. After a failed write HDF5 1.10
// keeps the file open and its exit handler crashes closing it again (`ibms run` leaves with
// _Exit), so the failing writes run in a child that leaves with _exit.
std::string in_child(const std::function<std::string()>& body) {
  int pipe_ends[2];
  if (pipe(pipe_ends) != 0) return "pipe failed";
  const pid_t child = fork();
  if (child == 0) {
    close(pipe_ends[0]);
    std::string text;
    try {
      text = body();
    } catch (const std::exception& e) {
      text = std::string("unexpected exception: ") + e.what();
    }
    const ssize_t written = ::write(pipe_ends[1], text.data(), text.size());
    _exit(written == static_cast<ssize_t>(text.size()) ? 0 : 1);
  }
  close(pipe_ends[1]);
  std::string text;
  char buffer[512];
  for (ssize_t n; (n = ::read(pipe_ends[0], buffer, sizeof buffer)) > 0;) text.append(buffer, static_cast<std::size_t>(n));
  close(pipe_ends[0]);
  int status = 0;
  waitpid(child, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) text += " (child did not exit cleanly)";
  return text;
}

// The kind of exception `write` throws and its message.
std::string outcome_of(const std::function<void()>& write) {
  try {
    write();
  } catch (const ibms::OutputError& e) {
    return std::string("OutputError: ") + e.what();
  } catch (const ibms::InputError& e) {
    return std::string("InputError: ") + e.what();
  }
  return "no error";
}

}  // namespace

BOOST_AUTO_TEST_CASE(failed_hdf5_dataset_writes_are_output_errors_before_any_flush) {
  fs::create_directories(dir);
  const fs::path h5 = dir / "out.h5";
  const ibms::Grid grid(128, 128, 1.0, 1.0);
  const std::vector<double> field(128 * 128, 0.5);  // 128 kB, beyond the sieve buffer
  for (const std::string kind : {"snapshot", "checkpoint"}) {
    const std::string outcome = in_child([&]() {
      ibms::OutputFile out(h5.string(), "(scene)", grid, "test", "none");
      out.append_series({{"time", "time", 0.0}});
      out.flush();  // the row written: the file is complete up to here
      const FileSizeLimit limit(fs::file_size(h5) + 4096);
      return outcome_of([&]() {
        if (kind == "snapshot") out.write_snapshot(0, 0.0, {{"u", "length/time", {128, 128}, field.data()}});
        else out.write_checkpoint({{"fluid_u", field}}, {{"time", 0.0}}, 1);
      });
    });
    BOOST_TEST_MESSAGE(kind << ": " << outcome);
    BOOST_TEST(outcome.rfind("OutputError: ", 0) == 0, kind << ": " << outcome);
    const std::string dataset = kind == "snapshot" ? "'u'" : "'fluid_u'";
    BOOST_TEST(outcome.find("out.h5: cannot write dataset " + dataset + ": File too large") != std::string::npos,
               kind << ": " << outcome);
    BOOST_TEST(outcome.find('\n') == std::string::npos);  // one line
    BOOST_TEST(!fs::exists(dir / "out.xmf.tmp"));
  }
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(failed_xdmf_write_is_an_output_error_and_leaves_no_temporary) {
  fs::create_directories(dir);
  const fs::path xmf = dir / "out.xmf";
  const ibms::Grid grid(64, 64, 1.0, 1.0);
  std::vector<ibms::XdmfSnapshot> snapshots;
  ibms::write_xdmf_sidecar(xmf.string(), "out.h5", grid, snapshots);  // a good sidecar first
  const std::string before = read(xmf);
  for (long step = 0; step < 50; ++step) {
    ibms::XdmfSnapshot snapshot;
    snapshot.group = "/snapshots/" + std::to_string(100000 + step);
    snapshot.time = 0.1 * step;
    snapshot.cell_arrays = {"u", "v", "p"};
    snapshots.push_back(snapshot);
  }
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
