"""Fails when git tracks a file that the demo, an example or a README command writes.

The outputs are read from where they are decided, not from a list kept here:
  - the demo's default output folder (`fs::path folder = "..."` in apps/demo/hyst_demo.cpp) and
    the Makefile's DEMO_OUT;
  - each example's default output folder (`else Path("...")` in examples/*.py, `fs::path("...")`
    after `argc > N ?` in examples/*.cpp);
  - every file or folder a command block of README.md writes (`--out X`, `--report X`,
    `--out-dir X`, `> X`, `mkdir -p X`), which a reader runs from the checkout.
A tracked path equal to one of them or inside one fails the check, naming both.

Usage: check_tracked_outputs.py CHECKOUT [--list]  (--list prints the outputs found)
Exit status 77 (skipped) outside a git checkout, e.g. an unpacked source archive.
"""

import re
import subprocess
import sys
from pathlib import Path


def demo_outputs(root):
    outputs = set()
    demo = (root / "apps/demo/hyst_demo.cpp").read_text()
    outputs.update(re.findall(r'fs::path folder = "([^"]+)"', demo))
    makefile = (root / "Makefile").read_text()
    outputs.update(re.findall(r"^DEMO_OUT\s*\?=\s*(\S+)", makefile, re.MULTILINE))
    return outputs


def example_outputs(root):
    outputs = set()
    for path in sorted((root / "examples").glob("*.py")):
        outputs.update(re.findall(r'else Path\("([^"]+)"\)', path.read_text()))
    for path in sorted((root / "examples").glob("*.cpp")):
        outputs.update(re.findall(r'argc > \d+ \? [^:;]+: fs::path\("([^"]+)"\)', path.read_text()))
    return outputs


def readme_outputs(root):
    text = (root / "README.md").read_text()
    outputs = set()
    for block in re.findall(r"^```sh\n(.*?)^```", text, re.MULTILINE | re.DOTALL):
        block = block.replace("\\\n", " ")
        for line in block.splitlines():
            command = line.split("#", 1)[0]
            if re.match(r"\s*make\b", command):
                continue  # make's own outputs: build/, out/demo (above)
            for option, value in re.findall(
                    r"(?:^|\s)(--out-dir|--out|--report|>|mkdir -p)(?:\s+|=|(?<=>))(\S+)", command):
                value = value.strip("'\"")
                if value in ("-", "&2", "/dev/null") or "$" in value:
                    continue
                outputs.add(value)
    return outputs


def normalised(path):
    return path.rstrip("/").removeprefix("./")


def main():
    root = Path(sys.argv[1]).resolve()
    found = {"demo": demo_outputs(root), "example": example_outputs(root),
             "README command": readme_outputs(root)}
    if "--list" in sys.argv:
        for kind, outputs in found.items():
            print(f"{kind}: {' '.join(sorted(outputs))}")
    # The sources must be readable as this script expects: each kind names something.
    empty = [kind for kind, outputs in found.items() if not outputs]
    if empty:
        print(f"FAIL: found no {', no '.join(empty)} outputs: has the way they are written "
              "changed? Update tests/repository/check_tracked_outputs.py")
        return 1
    listed = subprocess.run(["git", "-C", str(root), "ls-files", "-z"], capture_output=True,
                            check=False)
    if listed.returncode != 0:
        print(f"not a git checkout ({root}): skipped")
        return 77
    tracked = [path for path in listed.stdout.decode().split("\0") if path]
    bad = []
    for kind, outputs in found.items():
        for output in sorted(map(normalised, outputs)):
            for path in tracked:
                if path == output or path.startswith(output + "/"):
                    bad.append(f"{path} (written by the {kind} output {output})")
    if bad:
        print("FAIL: outputs are tracked by git (git rm -r --cached them; .gitignore):")
        print("\n".join(f"  {line}" for line in bad))
        return 1
    print(f"no output of the demo, the examples or the README commands is tracked "
          f"({sum(map(len, found.values()))} outputs, {len(tracked)} tracked files)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
