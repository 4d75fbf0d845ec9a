#!/usr/bin/env python3
"""Checks cmake/oiio_load_order.py on a small family of shared libraries built here.

root needs a and b; b needs deep. `deep` binds many of its own symbols at load, so it
should come first; `a` and `deep` both define the strong symbol `shared_counter`, which
root uses: `a` (first in the original breadth-first order) must keep defining it, so
the script has to move `a` back in front of `deep`.

usage: oiio_load_order_test.py SCRIPT CXX_COMPILER WORK_DIR
"""
import os
import subprocess
import sys


def build(compiler, work_dir, name, source, needed=()):
    path = os.path.join(work_dir, f"lib{name}.so")
    source_path = os.path.join(work_dir, f"{name}.cpp")
    with open(source_path, "w") as out:
        out.write(source)
    subprocess.run([compiler, "-shared", "-fPIC", "-o", path, source_path,
                    "-Wl,--no-as-needed", *needed], check=True)
    return path


def main():
    script, compiler, work_dir = sys.argv[1:4]
    os.makedirs(work_dir, exist_ok=True)
    # Exported pointers to exported variables: each is a symbol lookup at load time.
    self_bound = "".join(f"int deep_value{i} = {i};\nint* deep_pointer{i} = &deep_value{i};\n"
                         for i in range(50))
    deep = build(compiler, work_dir, "deep",
                 'extern "C" {\nint shared_counter = 2;\n' + self_bound + "}\n")
    a = build(compiler, work_dir, "a", 'extern "C" { int shared_counter = 1; }\n')
    b = build(compiler, work_dir, "b", 'extern "C" { int b_value = 3; }\n', [deep])
    root = build(compiler, work_dir, "root",
                 'extern "C" { extern int shared_counter; int* root_pointer = &shared_counter; }\n',
                 [a, b])
    output = os.path.join(work_dir, "order.txt")
    result = subprocess.run([sys.executable, script, root, compiler,
                             os.path.join(work_dir, "probe"), output],
                            capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"the script failed: {result.stdout}{result.stderr}")
    order = [os.path.basename(line.strip()) for line in open(output) if line.strip()]
    ours = [name for name in order if name in ("liba.so", "libb.so", "libdeep.so")]
    print("order:", ", ".join(ours))
    # deep is the most bound but must not take shared_counter from a; b binds nothing.
    if ours != ["liba.so", "libdeep.so", "libb.so"]:
        sys.exit(f"expected liba.so, libdeep.so, libb.so; got {ours} ({result.stdout})")


if __name__ == "__main__":
    main()
