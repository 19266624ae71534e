"""A LAMMPS data file as text: its title, header lines and sections (standard library only).

Shared by the tools that read or rewrite MESOPHYLL data files (replicate_tissue.py,
resample_tissue.py) and the checks that compare them (tests/published_growth.py).
"""


class DataFile:
    """The header lines and the sections of a LAMMPS data file, as lists of split lines."""

    def __init__(self, path):
        self.path = path
        with open(path) as f:
            lines = [line.rstrip("\n") for line in f]
        self.title = lines[0]
        self.header, self.sections, self.styles = [], {}, {}
        name = None
        for line in lines[1:]:
            words = line.split("#")[0].split()
            if not words:
                continue
            if words[0][0].isalpha():    # a section name, possibly with a '# style' comment
                name = " ".join(words)
                self.sections[name] = []
                self.styles[name] = line.split("#")[1].strip() if "#" in line else ""
            elif name is None:
                self.header.append(words)
            else:
                self.sections[name].append(words)

    def count(self, keyword):
        for words in self.header:
            if " ".join(words[1:]) == keyword:
                return int(words[0])
        return 0

    def bounds(self, axis):
        for words in self.header:
            if words[2:] == [f"{axis}lo", f"{axis}hi"]:
                return float(words[0]), float(words[1])
        raise SystemExit(f"{self.path}: the data file has no {axis}lo {axis}hi line")
