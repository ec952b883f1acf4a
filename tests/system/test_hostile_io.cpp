// SPDX-License-Identifier: GPL-2.0-or-later
/** @file test_hostile_io.cpp
 *  The command line under hostile conditions: odd files as scenes and rules files, output
 *  onto devices, links and protected files, failed writes, non-finite options, and
 *  SIGINT/SIGTERM in the middle of a run. Cases that need root are skipped otherwise. */
#include "helpers/cli_runner.h"
#include "helpers/tools.h"
#include "system/files.h"

#include <catch2/catch.hpp>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

using lagrange_test::cli_result;
using lagrange_test::read_file;
using lagrange_test::run_cli;
using lagrange_test::temporary_file;

namespace {

const std::string examples = std::string(LAGRANGE_SOURCE_DIR) + "/examples/";
const std::string double_pendulum = examples + "double_pendulum.lag";

std::string fresh_folder(const std::string& name)
{
    std::string folder = std::filesystem::path(temporary_file(name + ".stamp", "")).parent_path().string() + "/" + name;
    std::filesystem::remove_all(folder);
    std::filesystem::create_directory(folder);
    return folder;
}

std::vector<std::string> entries(const std::string& folder)
{
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(folder))
        names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

/// Starts `lagrange ARGS` in the background with `environment` (NAME=value entries);
/// returns its process id.
pid_t start_cli(const std::vector<std::string>& args, const std::vector<std::string>& environment,
                const std::string& output)
{
    pid_t child = fork();
    if (child == 0) {
        for (const std::string& e : environment)
            putenv(const_cast<char*>(e.c_str()));
        FILE* out = std::freopen(output.c_str(), "w", stderr);
        (void)out;
        std::vector<char*> argv{const_cast<char*>(LAGRANGE_BINARY)};
        for (const std::string& a : args)
            argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        execv(LAGRANGE_BINARY, argv.data());
        _exit(127);
    }
    return child;
}

/// Runs a shell command line that redirects lagrange's standard output itself; returns
/// the exit code and what lagrange wrote to standard error.
int shell(const std::string& command, std::string& err)
{
    std::string err_path = temporary_file("shell.err", "");
    int status = std::system(("timeout -s KILL 60 " + command + " 2>" + err_path).c_str());
    err = read_file(err_path);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

const std::string binary = LAGRANGE_BINARY;

bool wait_until(const std::function<bool()>& condition, double seconds)
{
    auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < end) {
        if (condition())
            return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return condition();
}

int exit_status(pid_t child)
{
    int status = 0;
    waitpid(child, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
}

} // namespace

TEST_CASE("hostile files: devices, pipes and folders as scenes and rules files", "[cli][hostile][io]")
{
    // /dev/zero and /dev/urandom are read in chunks and refused at the size limit.
    for (const char* device : {"/dev/zero", "/dev/urandom"}) {
        INFO(device);
        cli_result r = run_cli(device, "", 20);
        CHECK(r.exit_code == 2);
        CHECK(r.err.find("larger than 64 MB") != std::string::npos);
    }
    std::string header = "parameters m k\ncoordinates x\nT = 1/2*m*x'^2\nV = 1/2*k*x^2\n";
    cli_result zero_rules = run_cli(temporary_file("zero_rules.lag", header + "use \"/dev/zero\"\n"), "", 20);
    CHECK(zero_rules.exit_code == 2);
    CHECK(zero_rules.err.find(":5:1: error: cannot read the rules file: `/dev/zero` is larger than 16 MB") !=
          std::string::npos);
    // A folder is refused as a scene and as a rules file.
    std::string folder = fresh_folder("odd_files");
    CHECK(run_cli(folder).exit_code == 2);
    cli_result folder_rules = run_cli(temporary_file("folder_rules.lag", header + "use \"" + folder + "\"\n"));
    CHECK(folder_rules.exit_code == 2);
    CHECK(folder_rules.err.find("is a folder") != std::string::npos);
    // A named pipe that no one writes stops at the time budget.
    std::string fifo = folder + "/scene.fifo";
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    cli_result blocked = run_cli("--max-seconds 1 " + fifo, "", 10);
    CHECK(blocked.exit_code == 2);
    CHECK(blocked.err.find("gave no data for 1 s") != std::string::npos);
    CHECK(blocked.seconds < 5);
    // A pipe that is written is read.
    std::string scene = temporary_file("piped.lag", "parameters m k\ncoordinates x\nT = 1/2*m*x'^2\nV = 1/2*k*x^2\n");
    std::string out = folder + "/piped.out", err;
    CHECK(shell("sh -c '" + binary + " " + fifo + " --want equations >" + out + " & cat " + scene + " >" + fifo +
                    "; wait $!'",
                err) == 0);
    CHECK(read_file(out).find("Equations of motion") != std::string::npos);
    std::filesystem::remove_all(folder);
}

TEST_CASE("hostile files: a file that is not a rules file is never quoted", "[cli][hostile][io]")
{
    std::string secret = temporary_file("secret.txt", "root:x:0:0:secret-password-hash:/root:/bin/bash\n");
    std::string header = "parameters m k\ncoordinates x\nT = 1/2*m*x'^2\nV = 1/2*k*x^2\n";
    cli_result r = run_cli(temporary_file("use_secret.lag", header + "use \"" + secret + "\"\n"));
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("use_secret.lag:5:1: error:") != std::string::npos);
    CHECK(r.err.find("is not a rules file") != std::string::npos);
    CHECK(r.err.find("secret-password-hash") == std::string::npos);
    CHECK(r.err.find("/bin/bash") == std::string::npos);
}

TEST_CASE("hostile output: -o keeps a file's mode, follows links, never replaces a device", "[cli][hostile][io]")
{
    std::string folder = fresh_folder("odd_outputs");
    // A private file stays private.
    std::string secret = folder + "/private.txt";
    { std::ofstream(secret) << "old\n"; }
    REQUIRE(chmod(secret.c_str(), 0600) == 0);
    REQUIRE(run_cli(double_pendulum + " -o " + secret).exit_code == 0);
    struct stat info {};
    REQUIRE(stat(secret.c_str(), &info) == 0);
    CHECK((info.st_mode & 07777) == 0600);
    CHECK(read_file(secret) == run_cli(double_pendulum).out);
    // A symbolic link stays a link; the file it names is replaced.
    std::string target = folder + "/target.txt", link = folder + "/link.txt";
    { std::ofstream(target) << "old\n"; }
    REQUIRE(symlink(target.c_str(), link.c_str()) == 0);
    REQUIRE(run_cli(double_pendulum + " -o " + link).exit_code == 0);
    REQUIRE(lstat(link.c_str(), &info) == 0);
    CHECK(S_ISLNK(info.st_mode));
    CHECK(read_file(target) == run_cli(double_pendulum).out);
    // --plot through a planted link named like a temporary file: the link's target is untouched.
    std::string victim = folder + "/victim.txt", plot = folder + "/plot.svg";
    { std::ofstream(victim) << "precious\n"; }
    REQUIRE(symlink(victim.c_str(), (plot + ".tmp").c_str()) == 0);
    cli_result plotted = run_cli("simulate " + examples + "beats.lag --until 1 --plot " + plot, "", 60);
    if (plotted.exit_code == 0) { // without gnuplot there is no plot to write
        CHECK(read_file(plot).find("<svg") != std::string::npos);
    }
    CHECK(read_file(victim) == "precious\n");
    std::vector<std::string> expected{"link.txt", "plot.svg.tmp", "private.txt", "target.txt", "victim.txt"};
    if (plotted.exit_code == 0)
        expected.insert(expected.begin() + 1, "plot.svg");
    CHECK(entries(folder) == expected);
    std::filesystem::remove_all(folder);
}

TEST_CASE("hostile output: as root, -o keeps the owner and writes a device node, never replacing it",
          "[cli][hostile][io][root]")
{
    std::string folder = fresh_folder("root_outputs");
    std::string secret = folder + "/private.txt";
    { std::ofstream(secret) << "old\n"; }
    REQUIRE(chown(secret.c_str(), 65534, 65534) == 0);
    REQUIRE(run_cli(double_pendulum + " -o " + secret).exit_code == 0);
    struct stat info {};
    REQUIRE(stat(secret.c_str(), &info) == 0);
    CHECK(info.st_uid == 65534);
    CHECK(info.st_gid == 65534);
    std::string null_device = folder + "/null";
    REQUIRE(mknod(null_device.c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0);
    CHECK(run_cli(double_pendulum + " -o " + null_device).exit_code == 0);
    CHECK(run_cli("simulate " + examples + "beats.lag --until 1 --csv " + null_device, "", 60).exit_code == 0);
    REQUIRE(stat(null_device.c_str(), &info) == 0);
    CHECK(S_ISCHR(info.st_mode));
    CHECK(entries(folder) == std::vector<std::string>{"null", "private.txt"});
    std::filesystem::remove_all(folder);
}

TEST_CASE("hostile output: a failed write to standard output is exit 1 with a message", "[cli][hostile][io]")
{
    std::string err;
    CHECK(shell(binary + " " + double_pendulum + " >/dev/full", err) == 1);
    CHECK(err.find("cannot write to standard output") != std::string::npos);
    CHECK(shell(binary + " " + double_pendulum + " >&-", err) == 1);
    CHECK(err.find("standard output is closed") != std::string::npos);
    CHECK(shell(binary + " check " + double_pendulum + " >/dev/full", err) == 1);
    // With -o, a closed standard output does not matter.
    std::string folder = fresh_folder("closed_stdout");
    CHECK(shell(binary + " " + double_pendulum + " -o " + folder + "/out.txt >&-", err) == 0);
    CHECK(read_file(folder + "/out.txt") == run_cli(double_pendulum).out);
    std::filesystem::remove_all(folder);
}

TEST_CASE("hostile options: non-finite numbers and a step too small to count are refused", "[cli][hostile]")
{
    for (const std::string& args : {"--max-seconds nan " + double_pendulum, "--max-seconds inf " + double_pendulum,
                                    "simulate --until nan " + double_pendulum,
                                    "simulate --until inf " + double_pendulum,
                                    "simulate --tolerance nan " + double_pendulum}) {
        INFO(args);
        cli_result r = run_cli(args);
        CHECK(r.exit_code == 2);
        CHECK(r.err.find("finite") != std::string::npos);
    }
    std::string tiny = temporary_file("tiny_step.lag", "parameters m k\ncoordinates x\nT = 1/2*m*x'^2\n"
                                                       "V = 1/2*k*x^2\nvalues m = 1, k = 1\ninitial x = 1\n"
                                                       "simulate until 10 step 1e-300\n");
    cli_result r = run_cli("simulate " + tiny);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("tiny_step.lag:7:24: error: the step gives more than 10^7 output times") != std::string::npos);
}

TEST_CASE("signals: SIGTERM during the compile ends the compiler and leaves no folder", "[cli][hostile][signals]")
{
    std::string folder = fresh_folder("signal_compile");
    // A compiler that writes its process id, then hangs.
    std::string cc = folder + "/slow-cc";
    { std::ofstream(cc) << "#!/bin/sh\necho $$ > " << folder << "/cc.pid\nexec sleep 60\n"; }
    REQUIRE(chmod(cc.c_str(), 0755) == 0);
    std::string tmp = folder + "/tmp";
    std::filesystem::create_directory(tmp);
    pid_t run = start_cli({"simulate", double_pendulum}, {"LAGRANGE_CC=" + cc, "TMPDIR=" + tmp},
                          folder + "/stderr.txt");
    REQUIRE(wait_until([&] { return std::filesystem::exists(folder + "/cc.pid") && !read_file(folder + "/cc.pid").empty(); },
                       30));
    pid_t compiler = std::atoi(read_file(folder + "/cc.pid").c_str());
    REQUIRE(compiler > 0);
    CHECK(kill(compiler, 0) == 0);
    CHECK(!entries(tmp).empty()); // the private folder of the compile
    kill(run, SIGTERM);
    CHECK(exit_status(run) == 143);
    CHECK(wait_until([&] { return kill(compiler, 0) != 0; }, 5)); // the compiler was ended too
    CHECK(entries(tmp).empty());
    std::filesystem::remove_all(folder);
}

TEST_CASE("signals: SIGINT while -o is written removes the temporary file", "[cli][hostile][signals]")
{
    std::string folder = fresh_folder("signal_output");
    std::string out = folder + "/sweep.txt";
    // A sweep streams into the temporary file for a long time.
    pid_t run = start_cli({double_pendulum, "--sweep", "m=0.01..100:5000000", "--values", "M=1,l=1,g=9.81", "-o", out},
                          {}, folder + "/stderr.txt");
    REQUIRE(wait_until([&] { return entries(folder).size() == 2; }, 30)); // stderr.txt and the temporary
    kill(run, SIGINT);
    CHECK(exit_status(run) == 130);
    CHECK(entries(folder) == std::vector<std::string>{"stderr.txt"});
    std::filesystem::remove_all(folder);
}

TEST_CASE("native code: the compile stays within the time budget, then the interpreter runs", "[cli][hostile][budget]")
{
    std::string folder = fresh_folder("slow_compile");
    std::string cc = folder + "/slow-cc";
    { std::ofstream(cc) << "#!/bin/sh\nexec sleep 60\n"; }
    REQUIRE(chmod(cc.c_str(), 0755) == 0);
    cli_result r = [&] {
        lagrange_test::compiler_override slow(cc);
        return run_cli("--max-seconds 1 simulate " + double_pendulum + " --until 1", "", 30);
    }();
    CHECK(r.exit_code == 0);
    CHECK(r.out.find("compiling the equations took longer than the time budget") != std::string::npos);
    CHECK(r.seconds < 15);
    std::filesystem::remove_all(folder);
}
