// The result folder never removes what the toolkit did not write, and never leaves a folder that
// looks complete but is not.
#include <sys/stat.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "folder_snapshot.hpp"
#include "hm/core/input_error.hpp"
#include "hm/core/result_folder.hpp"

namespace fs = std::filesystem;
using hm::core::ResultFolder;
using hm::core::ResultTarget;
using hm::test::folder_snapshot;

namespace {

// A fresh folder for one test under the system temp folder, removed afterwards.
struct Sandbox {
  fs::path root = fs::temp_directory_path() / ("hmlattice-core-" + std::to_string(::getpid()));
  Sandbox() {
    fs::remove_all(root);
    fs::create_directories(root);
  }
  ~Sandbox() { fs::remove_all(root); }
  void write(const fs::path& file, const std::string& text) const {
    fs::create_directories((root / file).parent_path());
    std::ofstream(root / file) << text;
  }
};

// One finished result written through ResultFolder.
void write_result(const fs::path& target, const std::string& content, bool overwrite = false) {
  ResultFolder out(target, "--out", overwrite, "test " + content);
  std::ofstream(out.path() / "result.csv") << content;
  out.commit();
}

std::string refusal(const fs::path& target, bool overwrite = false) {
  try {
    hm::core::inspect_result_target(target, "--out", overwrite);
  } catch (const hm::InputError& e) {
    return e.what();
  }
  return "";
}

std::string read(const fs::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

TEST_CASE("A new result folder appears only on commit, with the marker, and an abandoned one leaves nothing",
          "[core]") {
  Sandbox box;
  const fs::path target = box.root / "deep" / "er" / "run";
  {
    ResultFolder out(target, "--out", false, "hmlattice fdm1d case.toml");
    std::ofstream(out.path() / "half.csv") << "t\n";
    CHECK_FALSE(fs::exists(target));
  }  // abandoned, as when a run fails: the parents it made go too
  CHECK(fs::is_empty(box.root));
  write_result(target, "1");
  CHECK(read(target / "result.csv") == "1");
  CHECK(hm::core::is_result_folder(target));
  CHECK(read(target / ".hmlattice").find("command_line = \"test 1\"") != std::string::npos);
  CHECK(folder_snapshot(box.root).size() == 5);  // deep, deep/er, run, its marker and result: no staging left
}

TEST_CASE("An empty folder is filled", "[core]") {
  Sandbox box;
  fs::create_directories(box.root / "empty");
  CHECK(hm::core::inspect_result_target(box.root / "empty", "--out", false) == ResultTarget::empty_folder);
  write_result(box.root / "empty", "x");
  CHECK(read(box.root / "empty" / "result.csv") == "x");
}

TEST_CASE("A folder holding the user's files is refused and every file stays, byte for byte", "[core]") {
  Sandbox box;
  box.write("victim/thesis.tex", "\\documentclass{article} years of work");
  box.write("victim/data/run.csv", "1,2,3\n");
  const auto before = folder_snapshot(box.root);
  CHECK_THROWS_AS(ResultFolder(box.root / "victim", "--out", true, "x"), hm::InputError);
  CHECK(folder_snapshot(box.root) == before);  // nothing removed, nothing staged beside it
  const std::string why = refusal(box.root / "victim", true);
  CHECK(why.find("--out = '" + (box.root / "victim").string() +
                 "' is a folder with files that hmlattice did not write") == 0);
  CHECK(why.find("allowed: a new or empty folder, or an earlier hmlattice result with --overwrite") !=
        std::string::npos);
  CHECK(why.find('\n') == std::string::npos);
}

TEST_CASE("An earlier result is refused without --overwrite and replaced with it", "[core]") {
  Sandbox box;
  const fs::path target = box.root / "res";
  write_result(target, "old");
  // Figures drawn later into a folder of their own inside it (the figure scripts give it its marker).
  box.write("res/figures/.hmlattice", "# hmlattice result folder: figures\nfiles = [\"figure.png\"]\n");
  box.write("res/figures/figure.png", "drawn later into the result folder");
  const auto before = folder_snapshot(box.root);
  CHECK(refusal(target) ==
        "--out = '" + target.string() +
            "' holds an earlier hmlattice result; add --overwrite to replace it, or choose another folder");
  CHECK_THROWS_AS(ResultFolder(target, "--out", false, "x"), hm::InputError);
  CHECK(folder_snapshot(box.root) == before);
  write_result(target, "new", true);
  CHECK(read(target / "result.csv") == "new");
  CHECK_FALSE(fs::exists(target / "figures"));   // the earlier result went as a whole
  CHECK(folder_snapshot(box.root).size() == 3);  // res, marker, result: nothing set aside is left
}

TEST_CASE("An earlier result holding a file the toolkit did not write is refused by --overwrite, naming it", "[core]") {
  Sandbox box;
  const fs::path target = box.root / "res";
  write_result(target, "old");
  CHECK(read(target / ".hmlattice").find("files = [\n  \"result.csv\",\n]\n") != std::string::npos);
  CHECK(hm::core::files_not_written_by_toolkit(target).empty());
  box.write("res/my_notes.txt", "what I saw in this run");
  box.write("res/figures/.hmlattice", "# hmlattice result folder: figures\nfiles = [\"a.png\"]\n");
  box.write("res/figures/a.png", "a figure");
  box.write("res/figures/b_edited.png", "the user's edit of it");
  CHECK(hm::core::files_not_written_by_toolkit(target) ==
        std::vector<std::string>{"figures/b_edited.png", "my_notes.txt"});
  const auto before = folder_snapshot(box.root);
  const std::string why = refusal(target, true);
  CHECK(why == "--out = '" + target.string() +
                   "' holds files hmlattice did not write ('figures/b_edited.png', "
                   "'my_notes.txt'), which --overwrite would remove; allowed: move them "
                   "out first, or choose another folder");
  CHECK_THROWS_AS(write_result(target, "new", true), hm::InputError);
  CHECK(folder_snapshot(box.root) == before);  // nothing removed, nothing staged beside it

  // A marker that lists nothing (an older version's) cannot vouch for any file: refused as well.
  box.write("old/.hmlattice", "# hmlattice result folder: written by the command below\n");
  box.write("old/result.csv", "1");
  CHECK(refusal(box.root / "old", true).find("whose marker lists no files") != std::string::npos);
}

TEST_CASE("A run that fails while replacing leaves the earlier result intact", "[core]") {
  Sandbox box;
  const fs::path target = box.root / "res";
  write_result(target, "old");
  const auto before = folder_snapshot(box.root);
  {
    ResultFolder out(target, "--out", true, "x");
    std::ofstream(out.path() / "result.csv") << "half";
  }  // the run threw: no commit
  CHECK(folder_snapshot(box.root) == before);
}

TEST_CASE("Files, links, devices, pipes, the working directory, folders above it, / and home are refused", "[core]") {
  Sandbox box;
  box.write("file.txt", "keep");
  box.write("dir/a.txt", "keep");
  fs::create_directory_symlink(box.root / "dir", box.root / "link");
  REQUIRE(::mkfifo((box.root / "pipe").c_str(), 0600) == 0);
  const auto before = folder_snapshot(box.root);
  for (bool overwrite : {false, true}) {
    CHECK(refusal(box.root / "file.txt", overwrite).find("' is a file;") != std::string::npos);
    CHECK(refusal(box.root / "file.txt" / "sub", overwrite).find("which is not a folder") != std::string::npos);
    CHECK(refusal(box.root / "link", overwrite).find("' is a symbolic link;") != std::string::npos);
    CHECK(refusal(box.root / "link/", overwrite).find("' is a symbolic link;") != std::string::npos);
    CHECK(refusal(box.root / "pipe", overwrite).find("' is a device, pipe or socket;") != std::string::npos);
    CHECK(refusal("/dev/null", overwrite) ==
          "--out = '/dev/null' is a device, pipe or socket; allowed: a new or empty folder, or an earlier hmlattice "
          "result with --overwrite");
    CHECK(refusal("/", overwrite).find("is the root folder") != std::string::npos);
    CHECK(refusal("", overwrite).find("--out = '' is empty") == 0);
    // A name the file system cannot take, under a new parent: refused before any computing (it was
    // found only when the finished run was moved into place).
    CHECK(refusal(box.root / "new" / std::string(256, 'x'), overwrite).find("has a name of 256 characters") !=
          std::string::npos);
    CHECK(
        refusal(box.root / std::string(256, 'y') / "run", overwrite).find("allowed: names of at most 255 characters") !=
        std::string::npos);
  }
  CHECK(folder_snapshot(box.root) == before);

  // The working directory and every folder above it, even when it is an earlier result.
  const fs::path cwd = fs::current_path();
  write_result(box.root / "res", "old");
  fs::create_directories(box.root / "res" / "sub");
  fs::current_path(box.root / "res" / "sub");
  for (const char* path : {".", "./", "..", "../", "../..", "../sub/.."})
    CHECK(refusal(path, true).find("is the working directory or a folder above it") != std::string::npos);
  CHECK(refusal(box.root / "res", true).find("is the working directory or a folder above it") != std::string::npos);
  fs::current_path(cwd);

  // The home directory, whatever it holds.
  const char* home = std::getenv("HOME");
  const std::optional<std::string> saved = home ? std::optional<std::string>(home) : std::nullopt;
  ::setenv("HOME", (box.root / "res").c_str(), 1);
  const std::string why = refusal(box.root / "res", true);
  if (saved)
    ::setenv("HOME", saved->c_str(), 1);
  else
    ::unsetenv("HOME");
  CHECK(why.find("is the home directory") != std::string::npos);
}

TEST_CASE("A trailing slash and a 250-character name work (the staging name has a fixed length)", "[core]") {
  Sandbox box;
  write_result(box.root.string() + "/res/", "a");
  CHECK(read(box.root / "res" / "result.csv") == "a");
  const std::string long_name(250, 'n');
  write_result(box.root / long_name, "b");
  CHECK(read(box.root / long_name / "result.csv") == "b");
  // "res/" names the same folder as "res": refused without --overwrite, replaced with it.
  CHECK(refusal(box.root.string() + "/res/").find("holds an earlier hmlattice result") != std::string::npos);
  write_result(box.root.string() + "/res//", "c", true);
  CHECK(read(box.root / "res" / "result.csv") == "c");
}

TEST_CASE("A target that changes while the run computes is left alone and the finished result is kept", "[core]") {
  Sandbox box;
  const fs::path target = box.root / "res";
  ResultFolder out(target, "--out", false, "x");
  std::ofstream(out.path() / "result.csv") << "finished";
  box.write("res/notes.txt", "the user's, written meanwhile");
  std::string message;
  try {
    out.commit();
  } catch (const std::runtime_error& e) {
    message = e.what();
  }
  CHECK(read(target / "notes.txt") == "the user's, written meanwhile");
  CHECK(fs::directory_iterator(target) != fs::directory_iterator());
  CHECK(message.find("they are complete in '" + out.path().string() + "'") != std::string::npos);
  CHECK(read(out.path() / "result.csv") == "finished");
  CHECK(fs::exists(out.path() / ".hmlattice"));
}

TEST_CASE("Only a regular marker file with the marker's first line makes a result folder", "[core]") {
  Sandbox box;
  box.write("a/.hmlattice", "something else\n");
  fs::create_directories(box.root / "b" / ".hmlattice");
  box.write("c/real", "");
  box.write("c/.hmlattice", "# hmlattice result folder: written by the command below\n");
  box.write("d/x", "");
  fs::create_symlink(box.root / "c" / ".hmlattice", box.root / "d" / ".hmlattice");
  CHECK_FALSE(hm::core::is_result_folder(box.root / "a"));
  CHECK_FALSE(hm::core::is_result_folder(box.root / "b"));
  CHECK(hm::core::is_result_folder(box.root / "c"));
  CHECK_FALSE(hm::core::is_result_folder(box.root / "d"));
  CHECK_THROWS_AS(hm::core::inspect_result_target(box.root / "a", "--out", true), hm::InputError);
}
