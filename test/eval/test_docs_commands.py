"""The commands and file names of the documentation work as written (issue 17, item 5).

Reads README.md and doc/*.md (and the usage comments of launch/*.launch), takes the shell
commands out of their code blocks and checks, without running them, that what they call is
there:
  - `rosrun sf_pkg X`: X is an executable that CMakeLists.txt builds (sf_add_filter,
    add_executable, also in add_subdirectory()'d CMakeLists) and installs (install(TARGETS),
    sf_add_filter without NO_INSTALL or TEST), or a script of the tree with mode 755 that the install
    rules install;
  - `roslaunch sf_pkg X`: launch/X exists;
  - `bash scripts/...`, `python3 tools/...` and the like: the file exists; a script called
    directly (`tools/eval/evaluate.py ...`) is also executable (mode 755 in git);
  - no command starts with a bare node name (`sf_nav3ctrl_ukf --replay ...` is "command not
    found" in a shell: `rosrun sf_pkg sf_nav3ctrl_ukf --replay ...`);
  - no command uses roslaunch's `$(find sf_pkg)` substitution, which a shell hands to GNU find;
  - every repository path the docs name (bags/..., config/..., tools/..., links) exists, and
    every sf_msgs/Name type has its sf_msgs/msg/Name.msg (or srv/Name.srv);
  - no document cites ../shared/..., which is not part of a user's clone.
The CMake reading is a small interpreter of the commands CMakeLists.txt uses to name its
executables (set, list, foreach, file(GLOB), get_filename_component), not CMake itself: a
target name it cannot work out fails the test rather than passing silently.
"""

import glob
import os
import re
import shlex
import stat
import subprocess
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.dont_write_bytecode = True

PACKAGE = "sf_pkg"
SHELL_LANGS = ("", "sh", "bash", "shell", "console")
# First-level folders of the repository: a path in the docs that starts with one of them is
# a repository file.
TOP_DIRS = ("bags", "cmake", "config", "doc", "launch", "scripts", "sf_estimation", "sf_filter",
            "sf_msgs", "test", "tools")
PLACEHOLDER = re.compile(r"[<>\[\]{}]|\.\.\.|\.\.\d|\$")
# Files the docs tell the reader to create in their own package (the tutorial's header).
USER_FILES = {"config/robot_ekf.h", "config/my_robot.h", "config/drone_3d.h"}


# ---------------------------------------------------------------------------------------------
# Markdown
# ---------------------------------------------------------------------------------------------
def doc_files(repo=REPO):
    return [os.path.join(repo, "README.md")] + sorted(glob.glob(os.path.join(repo, "doc", "*.md")))


def fenced_blocks(text):
    """[(language, first line number, [lines])] of the ``` blocks of a markdown text."""
    blocks, lang, start, body = [], None, 0, []
    for number, line in enumerate(text.splitlines(), 1):
        fence = re.match(r"^\s*```(.*)$", line)
        if fence and lang is None:
            lang, start, body = fence.group(1).strip().lower(), number + 1, []
        elif fence and not fence.group(1).strip():
            blocks.append((lang, start, body))
            lang = None
        elif lang is not None:
            body.append(line)
    return blocks


def prose(text):
    """The text outside the ``` blocks (the block lines blanked, numbering kept)."""
    out, inside = [], False
    for line in text.splitlines():
        if re.match(r"^\s*```", line):
            inside = not inside
            out.append("")
        else:
            out.append("" if inside else line)
    return "\n".join(out)


def inline_spans(text):
    return re.findall(r"`([^`\n]+)`", prose(text))


def logical_lines(lines):
    """Joins lines continued with a trailing backslash."""
    out, pending = [], ""
    for line in lines:
        if line.rstrip().endswith("\\"):
            pending += line.rstrip()[:-1] + " "
        else:
            out.append(pending + line)
            pending = ""
    if pending:
        out.append(pending)
    return out


def split_commands(line):
    """The simple commands of one shell line, as word lists (comments dropped, && ; | split).
    A line shlex cannot read (an unbalanced quote: output, not a command) gives none."""
    try:
        lexer = shlex.shlex(line, posix=True, punctuation_chars=";&|")
        lexer.whitespace_split = True
        lexer.commenters = "#"
        words = list(lexer)
    except ValueError:
        return []
    commands, current = [], []
    for word in words:
        if word and set(word) <= set(";&|"):
            if current:
                commands.append(current)
            current = []
        else:
            current.append(word)
    if current:
        commands.append(current)
    return commands


def doc_commands(repo=REPO):
    """[(where, words)] of every command in the shell code blocks of the docs, in inline code
    spans that start with rosrun/roslaunch, and in the usage comments of the launch files."""
    found = []
    for path in doc_files(repo):
        name = os.path.relpath(path, repo)
        with open(path, encoding="utf-8") as f:
            text = f.read()
        for lang, start, body in fenced_blocks(text):
            if lang not in SHELL_LANGS:
                continue
            for offset, line in enumerate(logical_lines(body)):
                for words in split_commands(line):
                    found.append(("%s:%d" % (name, start + offset), words))
        for span in inline_spans(text):
            if re.match(r"(rosrun|roslaunch)\s", span):
                for words in split_commands(span):
                    found.append(("%s (`%s`)" % (name, span), words))
    for path in sorted(glob.glob(os.path.join(repo, "launch", "*.launch"))):
        with open(path, encoding="utf-8") as f:
            text = f.read()
        for comment in re.findall(r"<!--(.*?)-->", text, re.S):
            for line in comment.splitlines():
                line = line.strip()
                if re.match(r"(rosrun|roslaunch|rosbag|rostopic)\s", line):
                    # the comment's explanation after a wide gap is not part of the command
                    line = re.split(r"\s{3,}", line)[0]
                    for words in split_commands(line):
                        found.append(("%s comment" % os.path.relpath(path, repo), words))
    return found


# ---------------------------------------------------------------------------------------------
# CMake: the executables a CMakeLists.txt builds and the files it installs
# ---------------------------------------------------------------------------------------------
def cmake_commands(text):
    """[(name, [arguments])] of a CMake file; comments dropped, ${...} left to the caller."""
    text = re.sub(r"#\[\[.*?\]\]", "", text, flags=re.S)
    commands, i, n = [], 0, len(text)
    call = re.compile(r"([A-Za-z_][A-Za-z0-9_]*)\s*\(")
    while i < n:
        if text[i] == "#":
            i = text.find("\n", i)
            i = n if i < 0 else i
            continue
        if text[i] == '"':  # a quoted argument outside a call does not happen; skip it
            i = text.find('"', i + 1) + 1 or n
            continue
        m = call.match(text, i)
        if not m or (i > 0 and (text[i - 1].isalnum() or text[i - 1] == "_")):
            i += 1
            continue
        j, depth, args, word, quoted = m.end(), 1, [], "", False
        while j < n and depth:
            c = text[j]
            if quoted:
                if c == "\\" and j + 1 < n:
                    word += text[j:j + 2]
                    j += 2
                    continue
                if c == '"':
                    quoted = False
                    args.append(word)
                    word = None
                else:
                    word += c
            elif c == '"':
                quoted, word = True, ""
            elif c == "#":
                j = text.find("\n", j)
                j = n if j < 0 else j
                continue
            elif c in "()":
                depth += 1 if c == "(" else -1
                if depth and word is not None:
                    word += c
                elif word:
                    args.append(word)
            elif c.isspace():
                if word:
                    args.append(word)
                word = ""
            else:
                word = (word or "") + c
            j += 1
        commands.append((m.group(1).lower(), args))
        i = j
    return commands


class CMakeTargets:
    """Executables built and programs installed by a CMakeLists.txt and its subdirectories.
    if() conditions are not evaluated: every branch counts (a target behind an option is
    still a target the docs may name, e.g. the benchmarks)."""

    def __init__(self, repo=REPO):
        self.repo = repo
        self.executables = set()
        self.installed = set()         # executables installed (install(TARGETS), sf_add_filter)
        self.programs = set()          # repository-relative paths of installed programs
        self.program_dirs = []         # (repository-relative dir, keeps source permissions)
        self.unresolved = []
        self._read(os.path.join(repo, "CMakeLists.txt"), {})

    def _expand(self, word, variables):
        for _ in range(10):
            new = re.sub(r"\$\{(\w+)\}", lambda m: variables.get(m.group(1), "\0"), word)
            if new == word:
                break
            word = new
        return word

    def _values(self, args, variables):
        out = []
        for arg in args:
            expanded = self._expand(arg, variables)
            out.extend(v for v in expanded.split(";") if v != "") if ";" in expanded \
                else out.append(expanded)
        return out

    def _read(self, path, variables):
        source_dir = os.path.dirname(path)
        variables = dict(variables, CMAKE_CURRENT_SOURCE_DIR=source_dir,
                         CMAKE_CURRENT_LIST_DIR=source_dir, PROJECT_NAME=PACKAGE)
        if source_dir == self.repo:
            variables.setdefault("CMAKE_SOURCE_DIR", source_dir)
        with open(path, encoding="utf-8") as f:
            commands = cmake_commands(f.read())
        self._run(commands, variables, source_dir)

    def _run(self, commands, variables, source_dir):
        i = 0
        while i < len(commands):
            name, args = commands[i]
            if name in ("function", "macro"):
                end = "end" + name
                depth, i = 1, i + 1
                while i < len(commands) and depth:
                    depth += {name: 1, end: -1}.get(commands[i][0], 0)
                    i += 1
                continue
            if name == "foreach":
                depth, j = 1, i + 1
                while j < len(commands) and depth:
                    depth += {"foreach": 1, "endforeach": -1}.get(commands[j][0], 0)
                    j += 1
                body = commands[i + 1:j - 1]
                loop_var, items = args[0], self._values(args[1:], variables)
                if items[:2] == ["IN", "LISTS"]:
                    items = [v for var in items[2:] for v in
                             self._values(["${%s}" % var], variables)]
                elif items[:1] == ["IN"]:
                    items = items[2:]
                for item in items:
                    variables[loop_var] = item
                    self._run(body, variables, source_dir)
                i = j
                continue
            self._command(name, args, variables, source_dir)
            i += 1

    def _command(self, name, args, variables, source_dir):
        values = self._values(args, variables)
        if name == "set" and values:
            rest = values[1:]
            for stop in ("CACHE", "PARENT_SCOPE"):
                if stop in rest:
                    rest = rest[:rest.index(stop)]
            variables[values[0]] = ";".join(rest)
        elif name == "list" and len(values) >= 2:
            op, var = values[0], values[1]
            items = [v for v in variables.get(var, "").split(";") if v]
            if op == "APPEND":
                items += values[2:]
            elif op == "TRANSFORM" and len(values) >= 4 and values[2] == "PREPEND":
                items = [values[3] + v for v in items]
            elif op == "TRANSFORM" and len(values) >= 4 and values[2] == "APPEND":
                items = [v + values[3] for v in items]
            variables[var] = ";".join(items)
        elif name == "file" and values and values[0] in ("GLOB", "GLOB_RECURSE"):
            patterns = [v for v in values[2:] if v not in ("CONFIGURE_DEPENDS", "LIST_DIRECTORIES")]
            matches = []
            for pattern in patterns:
                if not os.path.isabs(pattern):
                    pattern = os.path.join(source_dir, pattern)
                matches += sorted(glob.glob(pattern))
            variables[values[1]] = ";".join(matches)
        elif name == "get_filename_component" and len(values) >= 3:
            path, mode = values[1], values[2]
            base = os.path.basename(path)
            variables[values[0]] = {"NAME": base, "NAME_WE": base.split(".")[0],
                                    "DIRECTORY": os.path.dirname(path)}.get(mode, path)
        elif name == "add_subdirectory" and values:
            sub = os.path.join(source_dir, values[0], "CMakeLists.txt")
            if os.path.isfile(sub):
                self._read(sub, variables)
        elif name in ("add_executable", "sf_add_filter") and values:
            if "IMPORTED" in values or "ALIAS" in values:
                return
            self._target(values[0])
            if name == "sf_add_filter" and not {"NO_INSTALL", "TEST"} & set(values):
                self.installed.add(values[0])
        elif name == "install" and values and values[0] == "TARGETS":
            for v in values[1:]:
                if v.isupper():  # EXPORT, RUNTIME, LIBRARY, DESTINATION, ...
                    break
                self.installed.add(v)
        elif name in ("catkin_install_python", "install") and values and values[0] == "PROGRAMS":
            for v in values[1:]:
                if v == "DESTINATION":
                    break
                path = v if os.path.isabs(v) else os.path.join(source_dir, v)
                self.programs.add(os.path.relpath(path, self.repo))
        elif name == "install" and values and values[0] == "DIRECTORY":
            keep = "USE_SOURCE_PERMISSIONS" in values
            for v in values[1:]:
                if v == "DESTINATION":
                    break
                path = v if os.path.isabs(v) else os.path.join(source_dir, v)
                self.program_dirs.append((os.path.relpath(path, self.repo).rstrip("/"), keep))

    def _target(self, name):
        if "\0" in name or "$" in name:
            self.unresolved.append(name)
        else:
            self.executables.add(name)

    def installs_program(self, rel_path):
        """True when rel_path is installed as a program (PROGRAMS) or inside a directory that
        is installed with its source permissions."""
        if rel_path in self.programs:
            return True
        return any(keep and (rel_path + "/").startswith(d + "/") for d, keep in self.program_dirs)


# ---------------------------------------------------------------------------------------------
# Files of the repository
# ---------------------------------------------------------------------------------------------
def git_modes(repo=REPO):
    """{path: mode string} of the files git tracks, or None outside a git checkout."""
    try:
        out = subprocess.run(["git", "-C", repo, "ls-files", "-s"], capture_output=True,
                             text=True, check=True).stdout
    except (OSError, subprocess.CalledProcessError):
        return None
    modes = {}
    for line in out.splitlines():
        meta, _, path = line.partition("\t")
        modes[path] = meta.split()[0]
    return modes or None


def is_executable(rel_path, modes, repo=REPO):
    """Executable as a user's clone has it: git's mode when git tracks the file (a local
    chmod that is not committed does not count), else the file's own mode."""
    if modes is not None and rel_path in modes:
        return modes[rel_path] == "100755"
    path = os.path.join(repo, rel_path)
    return os.path.isfile(path) and bool(os.stat(path).st_mode & stat.S_IXUSR)


def scripts_named(name, repo=REPO):
    """Repository-relative paths of the files called name (what rosrun searches)."""
    out = []
    for root, dirs, files in os.walk(repo):
        dirs[:] = [d for d in dirs if not d.startswith(".") and d not in ("build", "__pycache__")]
        if name in files:
            out.append(os.path.relpath(os.path.join(root, name), repo))
    return sorted(out)


def repository_paths(text):
    """Repository-relative paths named in a text: words starting with a first-level folder
    of the repository (not an #include <...> name, not a placeholder)."""
    out = []
    pattern = re.compile(r"(?<![\w./<$-])((?:%s)/[\w./*+-]*)" % "|".join(TOP_DIRS))
    for line in text.splitlines():
        if re.match(r"\s*#\s*include", line):
            continue
        for m in pattern.finditer(line):
            path = m.group(1).rstrip(".,:;")
            end = m.end(1)
            following = line[end:end + 1]
            if following and (following in "<[{$" or PLACEHOLDER.search(path)):
                continue  # config/[config].h, pioneer_<date>.bag, position/{x,y}
            if path.endswith("/"):
                path = path.rstrip("/")
            out.append(path)
    return out


def is_header_name(path, repo=REPO):
    """sf_filter/core/fusion_core.hpp names a header as code includes it: the file is
    sf_filter/include/sf_filter/core/fusion_core.hpp."""
    top = path.split("/")[0]
    return os.path.isfile(os.path.join(repo, top, "include", path))


def markdown_links(text):
    return [t for t in re.findall(r"\]\(([^)\s]+)\)", prose(text))
            if not re.match(r"[a-z]+:", t) and not t.startswith("#")]


# ---------------------------------------------------------------------------------------------
# The checks
# ---------------------------------------------------------------------------------------------
def command_problems(where, words, targets, modes, repo=REPO):
    """Problems of one command (a list of its words), as strings."""
    problems = []
    while words and re.match(r"^\w+=", words[0]):  # VAR=value command ...
        words = words[1:]
    if not words:
        return problems
    first = words[0]
    if "$(find " in " ".join(words) or "$(find" in words:
        problems.append("%s: `%s` uses roslaunch's $(find ...), which a shell hands to GNU "
                        "find: use $(rospack find %s)" % (where, " ".join(words), PACKAGE))
    if first == "rosrun" and len(words) >= 3 and words[1] == PACKAGE:
        name = words[2]
        if name in targets.executables:
            if name not in targets.installed:
                problems.append("%s: rosrun %s %s: built by CMakeLists.txt but not installed "
                                "(install(TARGETS ...))" % (where, PACKAGE, name))
            return problems
        found = scripts_named(name, repo)
        runnable = [p for p in found if is_executable(p, modes, repo)]
        if not found:
            problems.append("%s: rosrun %s %s: no executable built by CMakeLists.txt and no "
                            "script of that name" % (where, PACKAGE, name))
        elif not runnable:
            problems.append("%s: rosrun %s %s: %s is not executable (git mode 644: chmod 755)"
                            % (where, PACKAGE, name, ", ".join(found)))
        elif not any(targets.installs_program(p) for p in runnable):
            problems.append("%s: rosrun %s %s: %s is not installed as a program by "
                            "CMakeLists.txt" % (where, PACKAGE, name, ", ".join(runnable)))
        return problems
    if first == "roslaunch" and len(words) >= 3 and words[1] == PACKAGE:
        if not os.path.isfile(os.path.join(repo, "launch", words[2])):
            problems.append("%s: roslaunch %s %s: launch/%s does not exist"
                            % (where, PACKAGE, words[2], words[2]))
        return problems
    if first in ("bash", "sh", "python3", "/usr/bin/python3") and len(words) >= 2:
        script = words[1]
        if not script.startswith("-"):
            rel = workspace_relative(script)
            if rel is not None and not os.path.isfile(os.path.join(repo, rel)):
                problems.append("%s: %s %s: no such file in the repository" % (where, first, script))
        return problems
    rel = workspace_relative(first)
    if rel is not None:
        if not os.path.isfile(os.path.join(repo, rel)):
            problems.append("%s: %s: no such file in the repository" % (where, first))
        elif not is_executable(rel, modes, repo):
            problems.append("%s: %s is run directly but is not executable (git mode 644)"
                            % (where, first))
        return problems
    if first in targets.executables or re.match(r"^sf_\w+$", first):
        problems.append("%s: `%s` starts with the bare executable %s, which is not on PATH: "
                        "write `rosrun %s %s ...`" % (where, " ".join(words), first, PACKAGE, first))
    return problems


def workspace_relative(word):
    """Repository-relative path of a command word that names a repository file (also as
    src/sf_pkg/... from a workspace root), else None."""
    word = word[2:] if word.startswith("./") else word
    if word.startswith("src/%s/" % PACKAGE):
        word = word[len("src/%s/" % PACKAGE):]
    if word.split("/")[0] in TOP_DIRS and "/" in word and not PLACEHOLDER.search(word):
        return word
    return None


def is_message_type(word, repo=REPO):
    """sf_msgs/Name is the message or service type of sf_msgs/msg/Name.msg (srv/Name.srv)."""
    parts = word.split("/")
    return len(parts) == 2 and parts[0] == "sf_msgs" and any(
        os.path.isfile(os.path.join(repo, "sf_msgs", kind, parts[1] + "." + kind))
        for kind in ("msg", "srv"))


def path_problems(doc_path, text, repo=REPO):
    problems = []
    name = os.path.relpath(doc_path, repo)
    for path in repository_paths(text):
        if path in USER_FILES:
            continue
        if any(c in path for c in "*?"):
            if not glob.glob(os.path.join(repo, path)):
                problems.append("%s: %s matches no file" % (name, path))
        elif not os.path.exists(os.path.join(repo, path)) and not is_header_name(path, repo) \
                and not is_message_type(path, repo):
            problems.append("%s: %s does not exist" % (name, path))
    base = os.path.dirname(doc_path)
    for link in markdown_links(text):
        target = link.split("#")[0]
        if target and not os.path.exists(os.path.normpath(os.path.join(base, target))):
            problems.append("%s: link %s does not exist" % (name, link))
    return problems


class CMakeReadingTest(unittest.TestCase):
    """The interpreter behind the command checks, on a hand-written CMakeLists."""

    def test_loops_lists_and_globs(self):
        import tempfile
        with tempfile.TemporaryDirectory() as tmp:
            os.makedirs(os.path.join(tmp, "sub", "examples"))
            open(os.path.join(tmp, "sub", "examples", "demo.cpp"), "w").close()
            with open(os.path.join(tmp, "CMakeLists.txt"), "w") as f:
                f.write('set(CONFIGS a b) # comment (with parentheses)\n'
                        'set(MORE c)\nlist(TRANSFORM MORE PREPEND sf_)\n'
                        'foreach(config ${CONFIGS})\n  sf_add_filter(sf_${config} x.h)\nendforeach()\n'
                        'sf_add_filter(sf_only_tested t.h TEST)\n'
                        'sf_add_filter(sf_not_installed n.h NO_INSTALL)\n'
                        'function(helper name)\n  add_executable(${name} y.cpp)\nendfunction()\n'
                        'if(FOO)\n  add_executable(node_${MORE} "z.cpp")\nendif()\n'
                        'catkin_install_python(PROGRAMS tools/a.py tools/b.py\n'
                        '  DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})\n'
                        'install(DIRECTORY tools DESTINATION share USE_SOURCE_PERMISSIONS)\n'
                        'add_subdirectory(sub)\n')
            with open(os.path.join(tmp, "sub", "CMakeLists.txt"), "w") as f:
                f.write('file(GLOB EX CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/examples/*.cpp")\n'
                        'foreach(ex ${EX})\n  get_filename_component(n "${ex}" NAME_WE)\n'
                        '  set(t "sf_${n}")\n  add_executable(${t} "${ex}")\n'
                        '  list(APPEND EXES ${t})\nendforeach()\n'
                        'install(TARGETS ${EXES} RUNTIME DESTINATION bin)\n')
            targets = CMakeTargets(tmp)
        self.assertEqual(targets.executables,
                         {"sf_a", "sf_b", "sf_only_tested", "sf_not_installed", "node_sf_c",
                          "sf_demo"})
        self.assertEqual(targets.installed, {"sf_a", "sf_b", "sf_demo"})
        self.assertEqual(targets.unresolved, [])
        self.assertEqual(targets.programs, {"tools/a.py", "tools/b.py"})
        self.assertTrue(targets.installs_program("tools/sub/c.py"))
        self.assertFalse(targets.installs_program("scripts/c.sh"))

    def test_package_targets(self):
        targets = CMakeTargets()
        self.assertEqual(targets.unresolved, [], "target names CMakeLists.txt gives that this "
                         "test cannot work out")
        for name in ("sf_train_kf", "sf_nav3ctrl_ukf", "sf_diff_drive_odom_imu", "sf_soccer_cwa_x",
                     "sf_moving_train", "sf_wang_table2", "sf_fusion_core_benchmark",
                     "sf_estimation_benchmark"):
            self.assertIn(name, targets.executables)
            self.assertIn(name, targets.installed)
        # nodes and drivers only for tests are not installed (issue 17, item 8)
        for name in ("sf_test_imu_heading", "sf_test_faults_kf", "sf_test_soak_driver"):
            self.assertIn(name, targets.executables)
            self.assertNotIn(name, targets.installed)


class ShellWordsTest(unittest.TestCase):
    def test_split_commands(self):
        self.assertEqual(split_commands("cd $WS && catkin_make -j1  # build"),
                         [["cd", "$WS"], ["catkin_make", "-j1"]])
        self.assertEqual(split_commands('roslaunch sf_pkg x.launch play_args:="-u 20"'),
                         [["roslaunch", "sf_pkg", "x.launch", "play_args:=-u 20"]])
        self.assertEqual(split_commands("error: it's an output line"), [])

    def test_bare_executable_is_a_problem(self):
        targets = CMakeTargets()
        modes = git_modes()
        self.assertTrue(command_problems("x", ["sf_nav3ctrl_ukf", "--replay", "b.bag"],
                                         targets, modes))
        self.assertEqual(command_problems("x", ["rosrun", PACKAGE, "sf_nav3ctrl_ukf", "--replay"],
                                          targets, modes), [])
        self.assertTrue(command_problems("x", ["roslaunch", PACKAGE, "no_such.launch"],
                                         targets, modes))
        self.assertTrue(command_problems("x", ["roslaunch", PACKAGE, "pioneer.launch",
                                               "bag:=$(find", "sf_pkg)/bags/a.bag"], targets, modes))

    def test_repository_paths(self):
        self.assertEqual(repository_paths("see `config/train_kf.h`, tools/eval/*.py and "
                                          "config/[config].h, #include <sf_filter/core/x.hpp>"),
                         ["config/train_kf.h", "tools/eval/*.py"])
        self.assertTrue(is_message_type("sf_msgs/OutputEntityStamped"))
        self.assertFalse(is_message_type("sf_msgs/NoSuchMessage"))
        self.assertEqual(path_problems(os.path.join(REPO, "doc", "x.md"),
                                       "sf_msgs/StateEstimateStamped and sf_msgs/Nothing"),
                         ["doc/x.md: sf_msgs/Nothing does not exist"])


class DocsCommandsTest(unittest.TestCase):
    """The package's own docs."""

    @classmethod
    def setUpClass(cls):
        cls.targets = CMakeTargets()
        cls.modes = git_modes()

    def test_commands_name_what_exists(self):
        commands = doc_commands()
        self.assertGreater(len(commands), 30, "the docs' commands were not found")
        problems = []
        for where, words in commands:
            problems += command_problems(where, words, self.targets, self.modes)
        self.assertEqual(problems, [], "\n" + "\n".join(problems))

    def test_named_files_exist(self):
        problems = []
        for path in doc_files():
            with open(path, encoding="utf-8") as f:
                problems += path_problems(path, f.read())
        self.assertEqual(problems, [], "\n" + "\n".join(problems))

    def test_launch_files_start_what_exists(self):
        """<node pkg="sf_pkg" type="X"> of the shipped launch files: X is built or is an
        installed executable script (a type made of $(arg ...) is left out)."""
        problems = []
        for path in sorted(glob.glob(os.path.join(REPO, "launch", "*.launch"))):
            with open(path, encoding="utf-8") as f:
                text = re.sub(r"<!--.*?-->", "", f.read(), flags=re.S)
            for node in re.findall(r"<node\b[^>]*>", text):
                pkg = re.search(r'\bpkg="([^"]*)"', node)
                node_type = re.search(r'\btype="([^"]*)"', node)
                if not pkg or not node_type or pkg.group(1) != PACKAGE or "$(" in node_type.group(1):
                    continue
                where = "%s <node type=%s>" % (os.path.relpath(path, REPO), node_type.group(1))
                problems += command_problems(where, ["rosrun", PACKAGE, node_type.group(1)],
                                             self.targets, self.modes)
        self.assertEqual(problems, [], "\n" + "\n".join(problems))

    def test_tools_with_a_main_are_executable(self):
        """A tools/ script with a #! line and a main runs as `tools/...` and `rosrun sf_pkg`."""
        problems = []
        for path in sorted(glob.glob(os.path.join(REPO, "tools", "**", "*.py"), recursive=True)):
            with open(path, encoding="utf-8") as f:
                text = f.read()
            rel = os.path.relpath(path, REPO)
            if text.startswith("#!") and "__main__" in text:
                if not is_executable(rel, self.modes):
                    problems.append("%s has a main but is not executable (chmod 755)" % rel)
                if not self.targets.installs_program(rel):
                    problems.append("%s is not installed as a program" % rel)
        self.assertEqual(problems, [], "\n" + "\n".join(problems))

    def test_no_shared_folder_cited(self):
        cited = []
        paths = doc_files() + sorted(glob.glob(os.path.join(REPO, "launch", "*.launch")))
        for path in paths:
            with open(path, encoding="utf-8") as f:
                for number, line in enumerate(f, 1):
                    if "../shared" in line:
                        cited.append("%s:%d" % (os.path.relpath(path, REPO), number))
        self.assertEqual(cited, [], "../shared/ is not in a user's clone: cite the document "
                         "by its title instead")


if __name__ == "__main__":
    unittest.main()
