"""Traceability (after MOOSE's requirement traceability matrix): each section of docs/method.md is a
requirement, identified by its number (M1.9, M3.7, MA8, ...); the tests that cite it (a 'method.md §N'
in the test's own sources, as test_method_citations checks them) trace to it, each with its
verdict at this build from ctest's own logs; the sections no test cites are listed. Then every test
of the build with the claim its source states first and its verdict. Nothing is hard-coded: the
sections come from docs/method.md, the tests and their sources from ctest's list in the build."""
import glob
import json
import os
import re
import subprocess
from collections import OrderedDict

from report_latex import TABLE_PT, esc, first_sentence, join_lines, longtable, md_text, tt

# A section number: 2, 1.9, A8, A10a. A citation is 'method.md §N', or one 'method.md' with a list of
# sections each written with its '§' ('method.md §1.9, §A8', '§4 and §A9'); test_method_citations.sh
# reads the same form.
SECTION = r"A?\d+(?:\.\d+)?[a-z]?"
CITATION = re.compile(r"method\.md\s*(§\s*%s(?:\s*(?:,|and|/)\s*§\s*%s)*)" % (SECTION, SECTION))
# The line right under a heading that marks a section as stating no requirement (method.md's legend).
DESCRIPTIVE = re.compile(r"\*Descriptive:\s*(.*?)\*\s*$")


def cited_in(text):
    """The section numbers that text cites, in order (each item of a list of citations)."""
    return [n for m in CITATION.finditer(text) for n in re.findall(r"§\s*(%s)" % SECTION, m.group(1))]


HEADING = re.compile(r"#{2,3} (%s)\.? (.*)" % SECTION)


def method_sections(source):
    """OrderedDict number -> title of docs/method.md's numbered headings (## 1., ### 1.9, ## A8.)."""
    sections = OrderedDict()
    with open(os.path.join(source, "docs", "method.md"), encoding="utf-8") as f:
        for line in f:
            m = HEADING.match(line.rstrip())
            if m:
                # without the provenance tags ([P] papers, [L] literature, [D] ibms's choice, joined
                # by '+'), which mean nothing without method.md's key
                sections[m.group(1)] = re.sub(r"\s*(?:\[[A-Z]\]\+?)+\s*$", "", m.group(2))
    return sections


def section_kinds(source):
    """(descriptive, groups): the sections that state no requirement. descriptive: OrderedDict number
    -> reason, from the paragraph '*Descriptive: reason.*' right under the heading (method.md's
    legend); groups: the headings with no text of their own before their first
    subsection (## 1. straight into ### 1.1), whose requirements are their subsections'. Every other
    numbered section is a requirement."""
    descriptive, groups = OrderedDict(), []
    with open(os.path.join(source, "docs", "method.md"), encoding="utf-8") as f:
        lines = [line.rstrip() for line in f]
    for i, line in enumerate(lines):
        m = HEADING.match(line)
        if not m:
            continue
        start = next((k for k in range(i + 1, len(lines)) if lines[k].strip()), len(lines))
        paragraph = []  # the first paragraph under the heading (its lines, up to a blank one)
        for text in lines[start:]:
            if not text.strip():
                break
            paragraph.append(text.strip())
        marker = DESCRIPTIVE.match(" ".join(paragraph))
        if marker:
            descriptive[m.group(1)] = marker.group(1).strip().rstrip(".")
        elif line.startswith("## ") and paragraph and paragraph[0].startswith("### ") and HEADING.match(paragraph[0]):
            groups.append(m.group(1))
    return descriptive, groups


def ctest_tests(build):
    """[(name, labels, command)] of every test the build defines (empty without ctest or a
    configured build)."""
    # ctest rewrites Testing/Temporary/LastTest.log even when it only lists the tests, which would
    # replace the verdicts of the build's last run (what the report reads) by an empty log: the logs
    # are put back as they were.
    logs = glob.glob(os.path.join(build, "Testing", "Temporary", "LastTest*.log"))
    kept = {}
    for path in logs:
        with open(path, "rb") as f:
            kept[path] = f.read()
    try:
        listing = subprocess.run(["ctest", "--show-only=json-v1"], cwd=build, capture_output=True, text=True,
                                 timeout=60)
        tests = json.loads(listing.stdout).get("tests", [])
    except (OSError, ValueError, subprocess.SubprocessError):
        return []
    finally:
        for path in glob.glob(os.path.join(build, "Testing", "Temporary", "LastTest*.log")):
            if path not in kept:
                os.remove(path)
        for path, content in kept.items():
            with open(path, "wb") as f:
                f.write(content)
    out = []
    for t in tests:
        labels = [v for p in t.get("properties", []) if p.get("name") == "LABELS" for v in p.get("value", [])]
        out.append((t["name"], labels, t.get("command", [])))
    return out


def test_sources(name, command, source):
    """The source files of a test: the scripts and sources its command names, else the program's
    source (verification/**/<program>.cpp, or a case's check.cpp)."""
    found = []
    for arg in command:
        if arg.startswith(source) and os.path.isfile(arg) and re.search(r"\.(sh|py|cpp|cmake)$", arg):
            found.append(arg)
    if command:
        program = os.path.basename(command[0])
        found += glob.glob(os.path.join(source, "verification", "**", program + ".cpp"), recursive=True)
        found += glob.glob(os.path.join(source, "bench", program + ".cpp"))
        found += validation_programs(source).get(program, [])
    return sorted(set(found))


_programs = {}


def validation_programs(source):
    """program -> its source files, from the add_executable lines of validation/**/CMakeLists.txt
    (a check program is named after no case folder in particular: cavity_check serves four)."""
    if source not in _programs:
        found = {}
        for cmake in glob.glob(os.path.join(source, "validation", "**", "CMakeLists.txt"), recursive=True):
            with open(cmake, encoding="utf-8", errors="replace") as f:
                text = f.read()
            for m in re.finditer(r"add_executable\(\s*(\w+)\s+([^)]*)\)", text):
                found[m.group(1)] = [os.path.join(os.path.dirname(cmake), src) for src in m.group(2).split()
                                     if src.endswith(".cpp")]
        _programs[source] = found
    return _programs[source]


def first_claim(paths):
    """The first sentence of the first source's leading comment (its stated claim), whole, and that
    source's path: (claim, path), ("", None) without one. List items of the comment read as clauses
    (report_latex.join_lines); the sentence ends at a full stop, not at a semicolon, an ellipsis, an
    abbreviation or inside brackets (report_latex.sentence_ends)."""
    for path in paths:
        try:
            with open(path, encoding="utf-8", errors="replace") as f:
                lines = f.read().splitlines()
        except OSError:
            continue
        # C and C++ comments are '//' lines ('#include' is code), scripts' and CMake's '#' lines
        marker = r"//+" if re.search(r"\.(cpp|hpp|h|cc)$", path) else r"#+"
        text = []
        for line in lines:
            s = line.strip()
            if s.startswith("#!") or (not text and not s):
                continue
            m = re.match(r"(%s)\s?(.*)" % marker, s)
            if not m:
                break
            text.append(m.group(2))
        claim = join_lines(text)
        claim = re.sub(r"^Claims?(,? labels? \w+)?( \([^)]*\))?:\s*", "", claim)
        if claim:
            return first_sentence(claim), path
    return "", None


def cited_sections(paths):
    cited = set()
    for path in paths:
        try:
            with open(path, encoding="utf-8", errors="replace") as f:
                cited.update(cited_in(f.read()))
        except OSError:
            continue
    return cited


def traceability_section(out, source, tests, ctest_results):
    """tests: ctest_tests(build); ctest_results: the verdicts of ctest's logs (report_data)."""
    if not tests:
        return
    status = {t["name"]: t["status"] for t in ctest_results}
    sections = method_sections(source)
    traced = OrderedDict((n, []) for n in sections)
    rows = []
    for name, labels, command in tests:
        paths = test_sources(name, command, source)
        verdict = status.get(name, "not run")
        for n in cited_sections(paths):
            key = n if n in traced else n.split(".")[0]
            if key in traced:
                traced[key].append((name, verdict))
        rows.append((name, labels, first_claim(paths), verdict))
    out.append(r"\section{Traceability: method sections, tests, verdicts}\label{sec:trace}")
    n_run = sum(1 for r in rows if r[3] != "not run")
    out.append("Each numbered section of \\texttt{docs/method.md} is a requirement, named M\\textit{n}, unless it states "
               "none: a section marked \\emph{Descriptive} under its heading (sources, summaries of schemes, open "
               "questions), or a heading with no text of its own, which groups its subsections. A test traces "
               "to a section when its sources cite it (\\texttt{method.md \\S n}, appendix sections as "
               "\\texttt{\\S A8}, the citations "
               "\\texttt{test\\_method\\_citations} keeps valid). Verdicts are ctest's own for this build "
               "(\\texttt{Testing/Temporary/LastTest*.log}: %d of the build's %d tests ran; \\emph{not run}: "
               "not in the logs, e.g.\\ a label this level leaves out)." % (n_run, len(rows)))

    def verdict_text(v):
        return {"pass": r"\textcolor{passgreen}{pass}", "FAIL": r"\textcolor{red}{\textbf{FAIL}}"}.get(v, esc(v))

    descriptive, groups = section_kinds(source)
    matrix = []
    untested = []
    for n, title in sections.items():
        cited = traced[n]
        if not cited:
            if n not in descriptive and n not in groups:
                untested.append("M%s" % n)
            continue
        passed = sum(1 for _, v in cited if v == "pass")
        failed = sum(1 for _, v in cited if v == "FAIL")
        names = ", ".join(tt(t) for t, _ in sorted(set(cited)))
        # the title whole, without its parenthesis (method.md's LaTeX math or a key, which
        # docs/method.md gives)
        short = re.sub(r"\s*\(.*$", "", title) or title
        matrix.append(["M%s" % esc(n), md_text(short), names, "%d / %d%s" % (passed, len(set(cited)),
                                                                             ", %d FAIL" % failed if failed else "")])
    out.append(r"{\fontsize{%g}{%g}\selectfont" % TABLE_PT + "\n" +
               longtable(r"l>{\raggedright\arraybackslash}p{4.2cm}>{\raggedright\arraybackslash}p{8.4cm}r",
                         ["req.", "method section", "tests citing it", "pass / tests"], matrix, size=None,
                         caption="Method sections of \\texttt{docs/method.md} and the tests that cite them.") + "}")
    n_requirements = sum(1 for n in sections if n not in descriptive and n not in groups)
    out.append("\\noindent\\emph{Requirement sections no test cites} (%d of %d requirements): %s.\n" %
               (len(untested), n_requirements, ", ".join(untested) if untested else "none"))
    if descriptive or groups:
        parts = []
        if descriptive:
            parts.append("descriptive (marked in \\texttt{docs/method.md}): " +
                         "; ".join("M%s (%s)" % (esc(n), md_text(why)) for n, why in descriptive.items()))
        if groups:
            parts.append("headings that group their subsections: " + ", ".join("M%s" % esc(n) for n in groups))
        out.append("\\noindent\\emph{Sections that state no requirement} (%d of %d sections): %s.\n" %
                   (len(descriptive) + len(groups), len(sections), "; ".join(parts)))
    # The test's name and, under it, the source whose header states the claim (where the rest of
    # that header is); the claim is the header's first sentence, whole. A long claim that an
    # earlier row printed from the same source (the runs and checks of one case share their
    # program) names that row's test instead of printing it again.
    table, first_row = [], {}
    for name, labels, (claim, path), v in rows:
        if len(claim) > 150 and (claim, path) in first_row:
            text = r"\emph{the claim of} %s \emph{(above; the same source)}" % tt(first_row[(claim, path)])
        else:
            first_row.setdefault((claim, path), name)
            text = md_text(claim) or "--"
        table.append([tt(name) + (r"\newline {\color{darkgray}%s}" % tt(os.path.relpath(path, source)) if path else ""),
                      esc(", ".join(labels)), text, verdict_text(v)])
    out.append(r"\subsection*{Every test with its stated claim}")
    out.append(r"{\fontsize{%g}{%g}\selectfont" % TABLE_PT + "\n" +
               longtable(r">{\raggedright\arraybackslash}p{4.4cm}l>{\raggedright\arraybackslash}p{8.8cm}l",
                         ["test (grey: the source of its claim)", "labels",
                          "claim (the first sentence of its source's header, whole)", "verdict"], table,
                         size=None, caption="Every test the build defines with its stated claim and its verdict "
                                            "in this build; the claim's source (grey, under the test) holds the "
                                            "rest of the header.") + "}")
