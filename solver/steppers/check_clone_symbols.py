#!/usr/bin/env python3
"""The AVX2 + FMA copy of the dop853 run (solver/steppers/dop853_fma.cc) replaces no baseline code.

Every function of that unit that the linker can see from other units (a global or weak symbol:
an inline function or a template instantiated on types the rest of the program shares) must be
free of VEX-encoded instructions, except the entry points run_dop853_fma, which are called only
where the CPU has AVX2 and FMA. A weak function with AVX2 code would be one of two copies of the
same name: the linker keeps either, and the baseline callers on a CPU without AVX2 would fault.

The same rule holds for dop853 in lanes (solver/steppers/dop853_lanes.cc) and for impacts driven
in lanes (solver/simulate_lanes.cc), whose entry points are baseline code that checks the CPU before calling into the unit: there no exported function may
have VEX code, and some function of the unit (a local one) must, or the unit was not compiled for
AVX2.

Usage: check_clone_symbols.py BUILD_DIR [OBJECT]   (OBJECT: dop853_fma.cc.o by default, found
below BUILD_DIR; exit 1 on a finding)
"""
import pathlib
import re
import subprocess
import sys

# the exported functions allowed AVX code, per object: the FMA copy's entry points; none in lanes
ENTRIES = {"dop853_fma.cc.o": "run_dop853_fma", "dop853_lanes.cc.o": None,
           "simulate_lanes.cc.o": None}


def exported_functions(obj, kinds="TWiu"):
    """global text, weak, indirect, unique by default; kinds="t" for the unit's local functions"""
    out = subprocess.run(["nm", "--defined-only", str(obj)], capture_output=True, text=True,
                         check=True).stdout
    names = {}
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 3 and parts[1] in kinds:
            names[parts[2]] = parts[1]
    return names


def first_vex_instruction(obj, names):
    out = subprocess.run(["objdump", "-d", "--no-show-raw-insn", str(obj)], capture_output=True,
                         text=True, check=True).stdout
    found, current = {}, None
    for line in out.splitlines():
        head = re.match(r"^[0-9a-f]+ <(.+)>:$", line)
        if head:
            current = head.group(1)
            continue
        if current not in names or current in found:
            continue
        fields = line.split("\t")
        if len(fields) >= 2 and fields[1].split():
            mnemonic = fields[1].split()[0]
            # VEX/EVEX-encoded SSE/AVX/FMA instructions all start with v (vmovsd, vfmadd231sd);
            # verr/verw are the only other x86 mnemonics that do
            if re.fullmatch(r"v[a-z0-9]+", mnemonic) and mnemonic not in ("verr", "verw"):
                found[current] = mnemonic
    return found


def main():
    name = sys.argv[2] if len(sys.argv) > 2 else "dop853_fma.cc.o"
    if name not in ENTRIES:
        print(f"unknown object {name}: one of {', '.join(ENTRIES)}")
        return 1
    entry = ENTRIES[name]
    objects = sorted(pathlib.Path(sys.argv[1]).rglob(name))
    if len(objects) != 1:
        print(f"expected one {name} below {sys.argv[1]}, found {len(objects)}")
        return 1
    names = exported_functions(objects[0])
    vex = first_vex_instruction(objects[0], names)
    entries = [n for n in vex if entry and entry in n]
    stand_ins = [n for n in vex if not (entry and entry in n)]
    for n in stand_ins:
        print(f"{names[n]} {n}: {vex[n]} (AVX code under a name the baseline code shares)")
    if entry and not entries:
        print(f"no {entry} with AVX code in {objects[0]}: the copy is not compiled for AVX2 + FMA")
        return 1
    if not entry:
        local = exported_functions(objects[0], "t")
        if not first_vex_instruction(objects[0], local):
            print(f"no function with AVX code in {objects[0]}: not compiled for AVX2 + FMA")
            return 1
    if stand_ins:
        print(f"{len(stand_ins)} stand-ins")
    elif entry:
        print(f"{objects[0]}: {len(names)} exported functions, AVX code only in the "
              f"{len(entries)} entry points")
    else:
        print(f"{objects[0]}: {len(names)} exported functions, none with AVX code")
    return 1 if stand_ins else 0


if __name__ == "__main__":
    sys.exit(main())
