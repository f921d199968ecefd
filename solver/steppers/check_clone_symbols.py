#!/usr/bin/env python3
"""The AVX2 + FMA copy of the dop853 run (solver/steppers/dop853_fma.cc) replaces no baseline code.

Every function of that unit that the linker can see from other units (a global or weak symbol:
an inline function or a template instantiated on types the rest of the program shares) must be
free of VEX-encoded instructions, except the entry points run_dop853_fma, which are called only
where the CPU has AVX2 and FMA. A weak function with AVX2 code would be one of two copies of the
same name: the linker keeps either, and the baseline callers on a CPU without AVX2 would fault.

Usage: check_clone_symbols.py BUILD_DIR   (finds dop853_fma.cc.o below it; exit 1 on a finding)
"""
import pathlib
import re
import subprocess
import sys

ENTRY = "run_dop853_fma"


def exported_functions(obj):
    out = subprocess.run(["nm", "--defined-only", str(obj)], capture_output=True, text=True,
                         check=True).stdout
    names = {}
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 3 and parts[1] in "TWiu":  # global text, weak, indirect, unique
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
    objects = sorted(pathlib.Path(sys.argv[1]).rglob("dop853_fma.cc.o"))
    if len(objects) != 1:
        print(f"expected one dop853_fma.cc.o below {sys.argv[1]}, found {len(objects)}")
        return 1
    names = exported_functions(objects[0])
    vex = first_vex_instruction(objects[0], names)
    entries = [n for n in vex if ENTRY in n]
    stand_ins = [n for n in vex if ENTRY not in n]
    for n in stand_ins:
        print(f"{names[n]} {n}: {vex[n]} (AVX code under a name the baseline code shares)")
    if not entries:
        print(f"no {ENTRY} with AVX code in {objects[0]}: the copy is not compiled for AVX2 + FMA")
        return 1
    print(f"{objects[0]}: {len(names)} exported functions, AVX code only in the "
          f"{len(entries)} entry points" if not stand_ins else f"{len(stand_ins)} stand-ins")
    return 1 if stand_ins else 0


if __name__ == "__main__":
    sys.exit(main())
