#!/usr/bin/python3
"""Checks that the README's usage lines agree with `hlr SUBCOMMAND --help`:
readme_usage.py HLR README.md

For every subcommand with a usage line (`./build/app/hlr SUB ...` in a code block, with its indented
continuation lines), the options named there must be exactly the options --help lists (but
-h/--help), and a default written as `--option ARG=VALUE` must be the one --help shows (`=VALUE`, or
"(default VALUE)" in its description); every default --help shows after `=` must be in the README.
One line per subcommand, "ok" or "FAIL" first; exit status 0 only when all agree.
"""
import re
import subprocess
import sys


def readme_usages(path):
    """{subcommand: [usage text, ...]} from the README's code blocks."""
    usages, current, in_code = {}, None, False
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("```"):
                in_code, current = not in_code, None
                continue
            if not in_code:
                continue
            m = re.match(r"\./build/app/hlr (\w+)\b(.*)", line)
            if m:
                current = m.group(1)
                usages.setdefault(current, []).append(m.group(2))
            elif current and line.startswith(" "):
                usages[current][-1] += " " + line.strip()
            else:
                current = None
    return usages


SHORT = {}  # short option -> long one, from --help ("-o,--output")


def readme_options(text):
    """{option: default or None} of one usage text; short options as their long names."""
    options = {}
    for m in re.finditer(r"(?<![\w-])(--[a-z][a-z-]*|-[a-z])((?:\s+[^\s\[\]|-][^\s\[\]]*)?)", text):
        argument = m.group(2).strip()
        default = argument.rsplit("=", 1)[1] if "=" in argument else None
        option = SHORT.get(m.group(1), m.group(1))
        if options.get(option) is None:
            options[option] = default
    return options


def help_options(hlr, command):
    """{option: (default after '=', default in the description)} from --help."""
    run = subprocess.run([hlr, command, "--help"], capture_output=True, text=True)
    if run.returncode != 0:
        raise RuntimeError(f"hlr {command} --help exits {run.returncode}")
    options, last = {}, None
    for line in run.stdout.splitlines():
        m = re.match(r"\s+(?:(-\w),)?(--[a-z][a-z-]*)(.*)", line)
        if m:
            last = m.group(2)
            if m.group(1):
                SHORT[m.group(1)] = last
            parts = re.split(r"\s{2,}", m.group(3).strip(), maxsplit=1)
            head = parts[0]
            description = parts[1] if len(parts) > 1 else ""
            shown = head.rsplit("=", 1)[1].split()[0] if "=" in head else None
            options[last] = [shown, None, description]
        elif last and line.startswith(" " * 10):
            options[last][2] += " " + line.strip()
    result = {}
    for option, (shown, _, description) in options.items():
        said = re.search(r"\(default ([^\s,);]+)\)", description)
        result[option] = (shown, said.group(1) if said else None)
    result.pop("--help", None)
    return result


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip().splitlines()[0], file=sys.stderr)
        return 2
    hlr, readme = argv[1], argv[2]
    failed = 0
    for command, texts in sorted(readme_usages(readme).items()):
        problems = []
        try:
            actual = help_options(hlr, command)
        except RuntimeError as e:
            problems.append(str(e))
            actual = {}
        documented = {}
        for text in texts:
            for option, default in readme_options(text).items():
                if documented.get(option) is None:
                    documented[option] = default
        for option in sorted(set(actual) - set(documented)):
            problems.append(f"{option} is in --help, not in the README")
        for option in sorted(set(documented) - set(actual)):
            problems.append(f"{option} is in the README, not in --help")
        for option in sorted(set(documented) & set(actual)):
            shown, said = actual[option]
            default = documented[option]
            if shown is not None and default != shown:
                problems.append(f"{option}: --help shows default {shown}, the README {default or 'none'}")
            elif shown is None and default is not None and default != said:
                problems.append(f"{option}: the README says default {default}, --help {said or 'none'}")
        if problems:
            failed += 1
            print(f"FAIL hlr {command}: " + "; ".join(problems))
        else:
            print(f"ok   hlr {command}: {len(documented)} options agree")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
