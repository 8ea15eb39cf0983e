// Drives the built program (IMPOSSIBLE_BINARY) as a hostile or careless user
// would, through bash (FIFOs, process substitution, /dev/full), with a time
// limit: every attack must end in exit 0 with correct output, or in exit 1 or
// 2 with one line on standard error, within seconds, leaving no file behind
// and replacing none.
#pragma once

#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "common/temp_dir.hpp"

namespace impossible::hostile {

namespace fs = std::filesystem;

struct Outcome {
    int status = -1;  // exit status; 124 when the time limit killed it
    std::string out, err;
    double seconds = 0;
    int err_lines() const {
        int n = 0;
        for (char c : err) n += c == '\n';
        return n;
    }
};

inline std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

inline void spit(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

// A star of `n` corners around the origin, alternately `outer` and `inner`
// metres from it, as a JSON polygon ([[x, z], ...]).
inline std::string star_polygon(int n, double outer, double inner) {
    std::string out = "[";
    char corner[64];
    for (int k = 0; k < n; ++k) {
        const double a = 2.0 * 3.14159265358979323846 * k / n, r = k % 2 ? inner : outer;
        std::snprintf(corner, sizeof corner, "%s[%.6f,%.6f]", k ? "," : "", r * std::cos(a), r * std::sin(a));
        out += corner;
    }
    return out + "]";
}

// Single-quotes a word for bash.
inline std::string q(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

inline const std::string kBin = q(IMPOSSIBLE_BINARY);

// Runs a bash script in `cwd` ($BIN is the program) under `timeout`. The
// script's own stdout and stderr are captured unless it redirects them.
inline Outcome run_script(const std::string& script, const fs::path& cwd, int limit_s = 30) {
    const fs::path out_file = cwd / ".stdout", err_file = cwd / ".stderr", script_file = cwd / ".script";
    spit(script_file,
         "BIN=" + kBin + "\nexport IMPOSSIBLE_INPUT_TIMEOUT_MS=${IMPOSSIBLE_INPUT_TIMEOUT_MS:-700}\n" + script + "\n");
    const std::string command = "cd " + q(cwd.string()) + " && timeout -k 5 " + std::to_string(limit_s) + " bash " +
                                q(script_file.string()) + " >" + q(out_file.string()) + " 2>" + q(err_file.string());
    const auto start = std::chrono::steady_clock::now();
    const int raw = std::system(command.c_str());
    Outcome run;
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    run.out = slurp(out_file);
    run.err = slurp(err_file);
    fs::remove(out_file);
    fs::remove(err_file);
    fs::remove(script_file);
    return run;
}

// Names in a directory but the test's own dot-files, sorted.
inline std::string listing(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    std::string out;
    for (const std::string& n : names) out += n + "\n";
    return out;
}

inline bool is_char_device(const std::string& path) {
    struct stat st {};
    return ::lstat(path.c_str(), &st) == 0 && S_ISCHR(st.st_mode);
}

// A fixture with its own directory holding a small valid layout, lay.json.
class Hostile : public test::TempDirTest {
protected:
    void SetUp() override {
        TempDirTest::SetUp();
        spit(dir_ / "lay.json", slurp(fs::path(IMPOSSIBLE_SOURCE_DIR) / "layouts/default.json"));
    }
    Outcome run(const std::string& script, int limit_s = 30) { return run_script(script, dir_, limit_s); }
    // A device node of the test's own, "full" (like /dev/full) or "null":
    // a program that wrongly replaces what is at its output path then
    // destroys only this node, never the system's. Creating one needs root
    // (CI runs as root); otherwise the system's node is used, which a user
    // cannot replace anyway.
    std::string device(const std::string& name) {
        const fs::path node = dir_ / name;
        const unsigned minor = name == "full" ? 7 : 3;
        if (::mknod(node.c_str(), S_IFCHR | 0666, makedev(1, minor)) == 0) return node.string();
        return "/dev/" + name;
    }
    // Expects a refusal: the status, one line on stderr holding `words`.
    void expect_refused(const Outcome& r, int status, const std::string& words) {
        EXPECT_EQ(r.status, status) << r.err;
        EXPECT_EQ(r.err_lines(), 1) << r.err;
        EXPECT_NE(r.err.find(words), std::string::npos) << r.err;
    }
};

}  // namespace impossible::hostile
