"""The tree's references hold: a page named with a heading ("docs/tuning.md,
"Size gate"") has that heading, a path named in a doc or a comment exists,
and nothing points outside the repository (a user's checkout has only the
tree). The README's tables of scores are make eval's."""
import os
import re
import subprocess

from conftest import TOP

SKIP = (".png", ".jpg", ".gif", ".mp4", ".bin", ".y4m")


def tracked():
    """The tree's text files, but this one (whose examples are no
    references)."""
    out = subprocess.run(["git", "ls-files", "--cached", "--others", "--exclude-standard"],
                         cwd=TOP, capture_output=True, text=True, check=True).stdout.split()
    here = os.path.relpath(os.path.abspath(__file__), TOP)
    return [f for f in out if not f.endswith(SKIP) and not f.startswith("tests/data/mot15/")
            and f != here and os.path.isfile(os.path.join(TOP, f))]


def text(f):
    with open(os.path.join(TOP, f), encoding="utf-8", errors="replace") as fh:
        return fh.read()


def headings():
    """{page: set of its headings}, a numbered heading also by its title."""
    out = {}
    for f in tracked():
        if f.endswith(".md"):
            out[f] = {re.sub(r"^\d+\. ", "", m.group(1)).strip()
                      for m in re.finditer(r"^#+ (.*)$", text(f), re.M)}
    return out


# docs/X.md, "Heading" or docs/X.md ("Heading"), across line breaks and
# comment markers.
REFERENCE = re.compile(r"((?:docs/)?(?:notes/)?[A-Za-z_]+\.md)`?,?\s*\(?\"([A-Z`][^\"()=%,]*)\"")
PATH = re.compile(r"(?<![\w/.-])((?:lib|tests|eval|scripts|tools|bench|docs|examples|cross)/"
                  r"[A-Za-z0-9_./{},-]*[A-Za-z0-9_}])")
# Paths a file names that are not in the tree by design: what a build
# makes, a Debian package holds or a pattern stands for.
NOT_IN_TREE = {"eval/dump-blobs", "bench/ddis-bench", "lib/python3/dist-packages",
               "examples/data/vtest.avi", "tests/fuzz/fuzz_", "docs/img/pets09-NNN.jpg",
               "python/abi_layout.c"}


def test_a_named_heading_exists():
    heads = headings()
    missing = []
    for f in tracked():
        flat = re.sub(r"\s*\n\s*(?://|#|\*)?\s*", " ", text(f))
        for m in REFERENCE.finditer(flat):
            page, title = m.group(1), m.group(2)
            pages = [p for p in heads if p.endswith(page)]
            if not any(h == title or (h.startswith(title) and not h[len(title)].isalnum())
                       for p in pages for h in heads[p]):
                missing.append("%s: %s, \"%s\"" % (f, page, title))
    assert not missing, "\n".join(missing)


def test_a_named_path_exists():
    missing = []
    for f in tracked():
        for m in PATH.finditer(text(f)):
            path = m.group(1)
            braces = re.match(r"(.*)\{([^}]*)\}(.*)", path)
            for p in ([braces.group(1) + x + braces.group(3) for x in braces.group(2).split(",")]
                      if braces else [path]):
                p = p.rstrip(".")
                if p not in NOT_IN_TREE and not os.path.exists(os.path.join(TOP, p)):
                    missing.append("%s: %s" % (f, p))
    assert not missing, "\n".join(sorted(set(missing)))


def test_nothing_points_outside_the_tree():
    # The shared folder beside a developer's checkout, and the engineering
    # note there, which a user's checkout does not have.
    outside = re.compile(re.escape("../" + "shared") + "|" + re.escape("ALGORITHM" + ".md"))
    found = [f for f in tracked() if outside.search(text(f))]
    assert not found, found


def test_the_method_is_described_and_linked():
    algorithm = text("docs/algorithm.md")
    assert "Liu, Feng" in algorithm or "Hui Liu, Yingying Feng" in algorithm
    assert "contour template" in algorithm.lower()
    for room in ("lib/api/", "lib/dsp/", "lib/track/", "lib/pixels/", "lib/template/",
                 "lib/appearance/", "lib/meanshift/"):
        assert room in algorithm, room
    assert "docs/algorithm.md" in text("README.md")
    assert "algorithm.md" in text("docs/README.md")


def _cells(line):
    return [c.strip() for c in line.strip().strip("|").split("|")]


def _plain(cell):
    """A table cell without bold marks."""
    return cell.replace("*", "").strip()


def _tracker(name):
    """A tracker's name without its version ("SORT (trackers 2.6.1)" ->
    "SORT (trackers)"), as the README names it."""
    name = re.sub(r"\s+\d+(\.\d+)+", "", _plain(name))
    return re.sub(r"\s+", " ", name).strip()


def _section_rows(md, heading):
    """The table rows (cells) under the first heading that starts so."""
    at = md.index("\n## " + heading)
    end = md.find("\n## ", at + 1)
    body = md[at:end if end >= 0 else len(md)]
    return [_cells(l) for l in body.splitlines()
            if l.startswith("|") and not l.startswith("|---")]


def _readme_table(readme, header):
    """The rows (cells) of the README's table whose header line starts so."""
    block = readme[readme.index(header):].split("\n\n")[0].splitlines()
    return [_cells(l) for l in block if not l.startswith("|---")]


def test_readme_tables_are_make_evals():
    """The README's tables of scores are docs/results.md's (make eval
    writes the one; the other is kept by hand and must follow)."""
    results, readme = text("docs/results.md"), text("README.md")
    # Over the six: HOTA, MOTA, IDF1, ID switches, precision, recall.
    over = {_tracker(r[0]): r[1:7] for r in _section_rows(results, "Over all")[1:]}
    rows = _readme_table(readme, "| tracker | HOTA | MOTA | IDF1 | ID switches |")[1:]
    assert len(rows) == len(over)
    for r in rows:
        assert [_plain(c) for c in r[1:7]] == over[_tracker(r[0])], r[0]
    # Sequence by sequence, MOTA / IDF1 from detections.
    table = _readme_table(readme, "| sequence | ctrack | ByteTrack |")
    names = [_tracker(c) for c in table[0][1:]]
    for r in table[1:]:
        seq = r[0]
        # Each tracker's first row from detections, by its name before any
        # bracket ("SORT (trackers)" -> "SORT"), as the README's header.
        got = {}
        for row in _section_rows(results, seq + " (")[1:]:
            if row[1] == "detections":
                got.setdefault(_tracker(row[0]).split(" (")[0], "%s / %s" % (row[4], row[5]))
        for name, cell in zip(names, r[1:]):
            assert _plain(cell) == got[name], (seq, name)
