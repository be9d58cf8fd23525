"""The product code's shape (code_shape.py, doc/design.md): no function over 60 lines in
sf_filter/ and sf_estimation/, no include cycle between sf_filter's include directories, node/
and replay/ apart; and the checker's own rules on hand-written C++."""

import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import code_shape  # noqa: E402

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")


def lengths(text, max_lines=0):
    """(first line, lines) of the functions of `text` longer than max_lines."""
    import tempfile
    with tempfile.NamedTemporaryFile("w", suffix=".cpp", delete=False) as f:
        f.write(text)
    try:
        return code_shape.long_functions(f.name, max_lines)
    finally:
        os.unlink(f.name)


class CheckerRules(unittest.TestCase):
    def test_function_counts_from_its_name_to_its_closing_brace(self):
        self.assertEqual(lengths("int f(int a)\n{\n  return a;\n}\n"), [(1, 4)])

    def test_control_blocks_classes_and_namespaces_are_not_functions(self):
        text = ("namespace n {\nstruct S : B {\n  int f() const noexcept {\n"
                "    if (x) {\n    } else {\n    }\n    for (;;) {\n    }\n"
                "    if constexpr (y) {\n    }\n    return 0;\n  }\n};\n}\n")
        self.assertEqual(lengths(text), [(3, 10)])

    def test_constructor_counts_its_initialiser_list(self):
        text = "S::S(int a)\n    : a_(a),\n      b_{a} {\n  run();\n}\n"
        self.assertEqual(lengths(text), [(1, 5)])

    def test_lambdas_count_on_their_own_and_in_their_function(self):
        text = ("void f() {\n  auto g = [&](int a) -> bool {\n    return a;\n  };\n"
                "  auto h = [this] {\n  };\n}\n")
        self.assertEqual(sorted(lengths(text)), [(1, 7), (2, 3), (5, 2)])

    def test_comments_strings_and_macros_are_not_code(self):
        text = ('#define M() { \\\n  x; \\\n}\n// void f() {\nconst char* s = "g() {";\n'
                'void h() {\n  /* } */\n}\n')
        self.assertEqual(lengths(text), [(6, 3)])

    def test_cycle_found_in_a_directory_graph(self):
        graph = {"replay": {"tuning": "replay/a.hpp", "core": "replay/b.hpp"},
                 "tuning": {"replay": "tuning/c.hpp"}, "core": {}}
        self.assertEqual(code_shape.include_cycles(graph), [["replay", "tuning"]])
        self.assertEqual(code_shape.include_cycles({"node": {"core": "x"}}), [])


class ProductShape(unittest.TestCase):
    def test_no_product_function_over_60_lines(self):
        problems = code_shape.function_violations(ROOT, 60)
        self.assertEqual(problems, [], "\n".join(problems))

    def test_no_include_cycle_between_sf_filter_directories(self):
        problems = code_shape.cycle_violations(ROOT)
        self.assertEqual(problems, [], "\n".join(problems))


    def test_node_and_replay_share_only_lower_layers(self):
        problems = code_shape.layer_violations(ROOT)
        self.assertEqual(problems, [], "\n".join(problems))


if __name__ == "__main__":
    unittest.main()
