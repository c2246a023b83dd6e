"""Checks the library layers of src/CMakeLists.txt against the sources' #include lines.

Every source file must belong to exactly one layer; the layers' links must form no cycle; a file
may include only headers of its own layer or of layers it links (directly or through them), and a
third-party header only when its layer links that library (or gets it from a layer's public link).
A header belongs to the layer that compiles the source of the same name, else to the layer of most
of its area's sources (hyst/identify/compare.hpp: the compare layer, of src/identify/compare.cpp).

Usage: check_layers.py <hyst source folder>; exit status 1 with one line per violation.
"""

import collections
import pathlib
import re
import sys

# Which link target a third-party #include needs.
THIRD_PARTY = {
    "ceres/": "Ceres::ceres",
    "nlopt.hpp": "NLopt::nlopt",
    "matio.h": "PkgConfig::MATIO",
    "zlib.h": "ZLIB::ZLIB",
    "nlohmann/": "nlohmann_json::nlohmann_json",
    "boost/": "Boost::headers",
    "fmt/": "fmt::fmt",
    "Eigen/": "Eigen3::Eigen",
    "unsupported/Eigen/": "Eigen3::Eigen",
}


def parse_layers(cmake_text):
    """Layer -> sources, and layer -> {PUBLIC: [...], PRIVATE: [...]} links, from the CMake text."""
    sources = {}
    for name, body in re.findall(r"^hyst_add_layer\((\w+)(.*?)\)", cmake_text, re.M | re.S):
        sources[name] = body.split()
    links = {name: {"PUBLIC": [], "PRIVATE": []} for name in sources}
    for name, body in re.findall(r"^target_link_libraries\(hyst_(\w+)(.*?)\)", cmake_text,
                                 re.M | re.S):
        if name not in links:
            continue
        visibility = "PUBLIC"
        for token in body.split():
            if token in ("PUBLIC", "PRIVATE", "INTERFACE"):
                visibility = "PUBLIC" if token == "INTERFACE" else token
            else:
                links[name][visibility].append(token)
    return sources, links


def layer_closure(links, problems):
    """Layer -> every layer it reaches through its links (itself included); reports cycles."""
    direct = {name: {token[len("hyst_"):] for section in link.values() for token in section
                     if token.startswith("hyst_") and token[len("hyst_"):] in links}
              for name, link in links.items()}
    closure = {}
    for start in direct:
        seen, stack = {start}, [start]
        while stack:
            for next_layer in direct[stack.pop()]:
                if next_layer == start:
                    problems.append(f"layer {start} links itself back through {sorted(direct[start])}")
                if next_layer not in seen:
                    seen.add(next_layer)
                    stack.append(next_layer)
        closure[start] = seen
    return closure


def third_party_allowed(links, closure):
    """Layer -> the third-party link targets its files may include."""
    allowed = {}
    for name in links:
        targets = set(links[name]["PUBLIC"]) | set(links[name]["PRIVATE"])
        for other in closure[name]:
            targets |= set(links[other]["PUBLIC"])
        allowed[name] = targets
    return allowed


def main(root):
    root = pathlib.Path(root)
    src, include = root / "src", root / "include"
    problems = []
    sources, links = parse_layers((src / "CMakeLists.txt").read_text())
    if not sources:
        print("no hyst_add_layer(...) found in src/CMakeLists.txt")
        return 1
    closure = layer_closure(links, problems)
    allowed_third_party = third_party_allowed(links, closure)

    layer_of = {}  # path relative to src/ or include/hyst/, without extension -> layer
    area_layers = collections.defaultdict(collections.Counter)
    for name, files in sources.items():
        for file in files:
            stem = file.rsplit(".", 1)[0]
            if stem in layer_of:
                problems.append(f"src/{file} is in layers {layer_of[stem]} and {name}")
            layer_of[stem] = name
            area_layers[file.split("/")[0]][name] += 1
    for file in sorted(src.rglob("*.cpp")):
        if file.relative_to(src).with_suffix("").as_posix() not in layer_of:
            problems.append(f"{file.relative_to(root)} is in no layer")

    def layer_of_file(relative):
        stem = relative.with_suffix("").as_posix()
        if stem in layer_of:
            return layer_of[stem]
        area = relative.parts[0]
        if not area_layers[area]:
            return None
        return area_layers[area].most_common(1)[0][0]

    files = [(path, src) for path in src.rglob("*.?pp")]
    files += [(path, include / "hyst") for path in (include / "hyst").rglob("*.hpp")]
    for path, base in sorted(files):
        layer = layer_of_file(path.relative_to(base))
        if layer is None:
            problems.append(f"{path.relative_to(root)}: its area has no layer")
            continue
        for number, line in enumerate(path.read_text().splitlines(), start=1):
            match = re.match(r'\s*#\s*include\s*[<"]([^>"]+)[>"]', line)
            if not match:
                continue
            name = match.group(1)
            where = f"{path.relative_to(root)}:{number} ({layer})"
            if name.startswith("hyst/"):
                target = layer_of_file(pathlib.Path(name[len("hyst/"):]))
            elif line.strip().split()[-1].startswith('"'):
                resolved = (path.parent / name).resolve()
                target = layer_of_file(resolved.relative_to(src.resolve())) \
                    if resolved.is_relative_to(src.resolve()) else None
            else:
                needed = next((target for prefix, target in sorted(THIRD_PARTY.items(),
                                                                   key=lambda item: -len(item[0]))
                               if name.startswith(prefix)), None)
                if needed and needed not in allowed_third_party[layer]:
                    problems.append(f"{where} includes <{name}> but does not link {needed}")
                continue
            if target is not None and target not in closure[layer]:
                problems.append(f"{where} includes {name} of layer {target}, which it does not link")
    problems = list(dict.fromkeys(problems))  # a cycle is met once from each of its layers' paths
    for problem in problems:
        print(problem)
    print(f"{len(sources)} layers, {len(layer_of)} sources, {len(problems)} violations")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
