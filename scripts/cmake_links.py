# What each library and program target links, read from the CMakeLists.txt files, and the
# folder that builds it: scripts/readme-files writes it into that folder's README ("Links")
# so a README's dependency line cannot drift from the build. A plain reading of the commands
# (add_library, add_executable, target_link_libraries and the runtime's fxkit_layer), with
# every if() branch taken: a link an option adds is listed too.
import os
import re

COMMAND = re.compile(r"\b(add_library|add_executable|target_link_libraries|fxkit_layer)\s*\(")
VISIBILITY = ("PUBLIC", "PRIVATE", "INTERFACE")


def arguments(text, start):
    """The words of the command whose '(' is at text[start - 1], up to its matching ')'."""
    depth, i = 1, start
    while i < len(text) and depth:
        depth += {"(": 1, ")": -1}.get(text[i], 0)
        i += 1
    return text[start:i - 1].split()


def without_comments(text):
    return "\n".join(line.split("#", 1)[0] for line in text.splitlines())


def read_targets(roots):
    """{target: {"folder": path, "links": {visibility: [items]}}} for the targets under roots."""
    targets, links = {}, {}
    for root in roots:
        for folder, dirs, files in os.walk(root):
            dirs[:] = sorted(d for d in dirs if not d.startswith(".") and d != "build")
            if "CMakeLists.txt" not in files:
                continue
            with open(os.path.join(folder, "CMakeLists.txt"), encoding="utf-8") as f:
                text = without_comments(f.read())
            for m in COMMAND.finditer(text):
                command, words = m.group(1), arguments(text, m.end())
                if not words or "$" in words[0]:
                    continue
                if command == "fxkit_layer":  # fxkit_layer(NAME DEPS...): fxkit_NAME, built by NAME/
                    name = "fxkit_" + words[0]
                    targets[name] = os.path.join(folder, words[0])
                    links.setdefault(name, {}).setdefault("PUBLIC", []).extend(words[1:])
                elif command in ("add_library", "add_executable"):
                    if "ALIAS" not in words:
                        targets[words[0]] = folder
                else:
                    visibility = "PUBLIC"
                    for w in words[1:]:
                        if w in VISIBILITY:
                            visibility = w
                        else:
                            links.setdefault(words[0], {}).setdefault(visibility, []).append(w)
    return {name: {"folder": folder, "links": links.get(name, {})} for name, folder in targets.items()}


def links_line(name, links):
    """`name` links, public: `a`, `b`; private: `c` (or: links nothing)."""
    parts = []
    for visibility in VISIBILITY:
        items = list(dict.fromkeys(links.get(visibility, [])))
        if items:
            parts.append(visibility.lower() + ": " + ", ".join("`" + i + "`" for i in items))
    return "`" + name + "` links " + ("; ".join(parts) if parts else "nothing") + "."
