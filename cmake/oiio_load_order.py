#!/usr/bin/env python3
"""Choose the order in which the image module names OpenImageIO's shared libraries.

Loading Debian's libOpenImageIO maps about 260 libraries and binds about 150,000
symbols. The dynamic linker looks each symbol up by walking the load scope in
breadth-first order until a library defines it, so a library that binds many of its
own symbols (C++ libraries such as OpenVDB bind tens of thousands: vtables, typeinfo,
inline functions) but sits far down the scope makes every one of those lookups skip
all the libraries before it. Naming the libraries in the module's DT_NEEDED list
ordered by how many bindings each receives shortens the average walk about five
times and halves the load time.

Reordering must not change what any symbol binds to (a library earlier in the scope
wins when two define the same name), so the order is checked: a probe library with
the new order is loaded and every (referencing library, symbol) -> definer binding is
compared with the original load. Only interchangeable copies of C++ inline entities
may move; where a library's own definition would lose to another library's, the
original definer is moved back in front and the check repeats. On any failure the
script writes an empty list and the module links OpenImageIO the usual way.

usage: oiio_load_order.py OIIO_LIBRARY CXX_COMPILER WORK_DIR OUTPUT
Writes OUTPUT: one library path per line, most-bound first (possibly empty).
"""
import collections
import os
import re
import subprocess
import sys

BINDING = re.compile(r"binding file (\S+) \[\d+\] to (\S+) \[\d+\]: \S+ symbol `([^']+)'")


def load_bindings(loader, library, work_dir):
    """Load `library` in a fresh interpreter with the linker's debug output on.

    Returns (the library's load scope without the program's own libraries,
    {(referencing file, symbol): definer} for the bindings the load made)."""
    log_prefix = os.path.join(work_dir, "ld-debug")
    for name in os.listdir(work_dir):
        if name.startswith("ld-debug."):
            os.remove(os.path.join(work_dir, name))
    environment = dict(os.environ, LD_DEBUG="scopes,bindings", LD_DEBUG_OUTPUT=log_prefix)
    subprocess.run([loader, library], env=environment, check=True, stdout=subprocess.DEVNULL)
    global_scope, scope, bindings = None, None, {}
    for name in os.listdir(work_dir):
        if not name.startswith("ld-debug."):
            continue
        with open(os.path.join(work_dir, name), errors="replace") as log:
            for line in log:
                if global_scope is None and "scope 0: " in line:
                    global_scope = set(line.split("scope 0:", 1)[1].split())
                elif scope is None and "scope 1: " + library in line:
                    scope = line.split("scope 1:", 1)[1].split()
                    continue
                match = BINDING.search(line)
                # The program's own start-up bindings are not part of the load.
                if match and match.group(1) not in (global_scope or ()):
                    bindings[(match.group(1), match.group(3))] = match.group(2)
        os.remove(os.path.join(work_dir, name))
    if scope is None:
        raise RuntimeError("no load scope for " + library + " in the linker's output")
    # Libraries already in the program's global scope are searched first anyway.
    return [path for path in scope if path not in (global_scope or ())], bindings


def ordered_dependencies(scope, bindings):
    """The scope's libraries (not the loaded library itself nor the dynamic linker),
    most-bound first; ties keep their original place."""
    received = collections.Counter(bindings.values())
    libraries = []
    for path in scope:
        if path != scope[0] and path not in libraries and "/ld-linux" not in path:
            libraries.append(path)
    return sorted(libraries, key=lambda path: -received[path])


def build_loader(compiler, work_dir):
    """A C++ program that dlopens its argument like crtc's module loader does (RTLD_LAZY,
    RTLD_LOCAL) with the C++ runtime already in the global scope, as in crtc, so that
    libstdc++'s own symbols keep binding to libstdc++ whatever the order."""
    source = os.path.join(work_dir, "loader.cpp")
    loader = os.path.join(work_dir, "loader")
    with open(source, "w") as out:
        out.write("#include <dlfcn.h>\n#include <string>\n"
                  "int main(int, char** argv) {\n"
                  "  std::string path = argv[1];\n"
                  "  return dlopen(path.c_str(), RTLD_LAZY | RTLD_LOCAL) ? 0 : 1;\n}\n")
    subprocess.run([compiler, "-o", loader, source, "-ldl"], check=True)
    return loader


def build_probe(compiler, libraries, library, work_dir):
    source = os.path.join(work_dir, "probe.cpp")
    probe = os.path.join(work_dir, "probe.so")
    with open(source, "w") as out:
        out.write("extern \"C\" void crt_load_order_probe() {}\n")
    subprocess.run([compiler, "-shared", "-fPIC", "-o", probe, source,
                    "-Wl,--no-as-needed", *libraries, library],
                   check=True, stdout=subprocess.DEVNULL)
    return probe


def definition_kinds(library, cache={}):
    """{symbol: nm's type letter} of the library's exported definitions."""
    if library not in cache:
        listing = subprocess.run(["nm", "-D", "--defined-only", library],
                                 check=True, capture_output=True, text=True).stdout
        kinds = {}
        for line in listing.splitlines():
            fields = line.split()
            if len(fields) >= 3:
                kinds[fields[2].split("@")[0]] = fields[1]
        cache[library] = kinds
    return cache[library]


def is_shared_copy(symbol, library):
    """Weak (W, V) and unique (u) definitions are the copies of one C++ entity (inline
    functions, template instances, typeinfo) that every library using it carries;
    the one-definition rule makes them interchangeable, so binding to another copy
    changes nothing. Any other definition is the library's own."""
    return definition_kinds(library).get(symbol, "?") in "WVu"


def rebound_definitions(original, reordered):
    """[(symbol, original definer, new definer)] for bindings that moved to a different
    library and are not interchangeable copies."""
    moved = set()
    for (file, symbol), definer in original.items():
        now = reordered.get((file, symbol), definer)
        if now != definer and not (is_shared_copy(symbol, definer)
                                   and is_shared_copy(symbol, now)):
            moved.add((symbol, definer, now))
    return sorted(moved)


def choose_order(loader, compiler, library, work_dir):
    scope, original = load_bindings(loader, library, work_dir)
    order = ordered_dependencies(scope, original)
    for _ in range(3):
        probe = build_probe(compiler, order, library, work_dir)
        _, reordered = load_bindings(loader, probe, work_dir)
        moved = rebound_definitions(original, reordered)
        if not moved:
            return order
        # A library that defined the symbol first must stay before the one now winning.
        for symbol, definer, now in moved:
            if order.index(definer) > order.index(now):
                order.remove(definer)
                order.insert(order.index(now), definer)
    symbol, definer, now = moved[0]
    raise RuntimeError(f"reordering would bind {symbol} to {now} instead of {definer}")


def main():
    library, compiler, work_dir, output = sys.argv[1:5]
    os.makedirs(work_dir, exist_ok=True)
    order = []
    try:
        loader = build_loader(compiler, work_dir)
        order = choose_order(loader, compiler, library, work_dir)
    except Exception as error:  # any failure only costs the faster load
        print(f"oiio_load_order: {error}; keeping OpenImageIO's own order")
    with open(output, "w") as out:
        out.writelines(path + "\n" for path in order)


if __name__ == "__main__":
    main()
