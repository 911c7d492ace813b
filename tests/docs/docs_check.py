"""Checks of the documentation as Markdown and as a site.

  docs_check.py markdown SOURCE_DIR
      Renders README.md, docs/*.md and bench/RESULTS.md with cmark-gfm (GitHub's CommonMark)
      and fails on a broken code fence (a closing fence with text after it, an unclosed
      fence), on a heading of the source that the rendering does not have (one swallowed into
      a code block), on a code block the source does not have, and on a relative link or
      image whose file does not exist.
  docs_check.py site SOURCE_DIR SITE_DIR
      Builds the site with `mkdocs build --strict` (which fails on a link to a page that does
      not exist) into SITE_DIR, then checks every link and image of every page it wrote: the
      file exists, and so does the anchor (`page.html#id`) in it (MkDocs 1.4 does not check
      anchors); every page of docs/ is in the site's nav; no page loads anything from the
      network.

Exit 77 (the test's SKIP_RETURN_CODE) when cmark-gfm or mkdocs is not installed; scripts/setup
installs both."""
import glob
import html
import os
import re
import shutil
import subprocess
import sys
from html.parser import HTMLParser
from urllib.parse import unquote, urlparse

SKIP = 77
FENCE = re.compile(r"^\s*(`{3,}|~{3,})(.*)$")  # (any indentation: as the author meant it)
HEADING = re.compile(r"^ {0,3}(#{1,6})\s+(.*?)(\s+#+)?\s*$")


class Page(HTMLParser):
    """The links, ids, headings and code blocks of an HTML page."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.links, self.ids, self.headings, self.pre, self.remote = [], set(), [], 0, []
        self._heading = None

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if "id" in a:
            self.ids.add(a["id"])
        if tag == "a" and a.get("href") is not None:
            self.links.append(a["href"])
        if tag == "img" and a.get("src") is not None:
            self.links.append(a["src"])
        if tag in ("script", "img") and re.match(r"^(https?:)?//", a.get("src") or ""):
            self.remote.append(a["src"])
        if tag == "link" and re.match(r"^(https?:)?//", a.get("href") or "") and a.get("rel") in ("stylesheet", "icon"):
            self.remote.append(a["href"])
        if tag == "pre":
            self.pre += 1
        if re.fullmatch(r"h[1-6]", tag):
            self._heading = [int(tag[1]), ""]

    def handle_data(self, data):
        if self._heading is not None:
            self._heading[1] += data

    def handle_endtag(self, tag):
        if re.fullmatch(r"h[1-6]", tag) and self._heading is not None:
            self.headings.append((self._heading[0], " ".join(self._heading[1].split())))
            self._heading = None


def parse(text):
    p = Page()
    p.feed(text)
    return p


def relative(link):
    """A link to a file of this tree (not a URL, not mail, not only an anchor)."""
    u = urlparse(link)
    return not (u.scheme or u.netloc or link.startswith("#") or link.startswith("/"))


def plain(markdown_heading):
    """A heading's text as a reader sees it: no code spans, emphasis or link targets."""
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", markdown_heading)
    text = text.replace("`", "").replace("**", "").replace("\\", "")
    text = re.sub(r"(?<!\w)[*_]([^*_]+)[*_](?!\w)", r"\1", text)
    return " ".join(html.unescape(text).split())


def source_structure(path, rel, problems):
    """The headings and code blocks of a Markdown file, read line by line as its author meant it."""
    headings, blocks, fence, opened = [], 0, None, 0
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    for number, line in enumerate(lines, 1):
        m = FENCE.match(line)
        if fence is None:
            if m:
                fence, opened = m.group(1), number
                blocks += 1
            else:
                h = HEADING.match(line)
                if h:
                    headings.append((len(h.group(1)), plain(h.group(2))))
        elif m and m.group(1)[0] == fence[0] and len(m.group(1)) >= len(fence):
            if m.group(2).strip():
                problems.append(f"{rel}:{number}: a closing fence with text after it ('{line.strip()}'): CommonMark "
                                f"reads it as a new block's opening, and the rest of the page as code")
            fence = None
    if fence is not None:
        problems.append(f"{rel}:{opened}: this code fence is never closed")
    return headings, blocks


def check_markdown(source):
    cmark = shutil.which("cmark-gfm")
    if not cmark:
        print("cmark-gfm is not installed (scripts/setup installs it): skipped")
        return SKIP
    files = [os.path.join(source, "README.md"), os.path.join(source, "bench", "RESULTS.md")]
    files += sorted(glob.glob(os.path.join(source, "docs", "*.md")))
    problems, links = [], 0
    for path in files:
        rel = os.path.relpath(path, source)
        headings, blocks = source_structure(path, rel, problems)
        r = subprocess.run([cmark, "--extension", "table", "--extension", "autolink", "--extension", "strikethrough",
                            path], capture_output=True, text=True)
        if r.returncode != 0:
            problems.append(f"{rel}: cmark-gfm failed: {r.stderr}")
            continue
        page = parse(r.stdout)
        rendered = [(level, " ".join(html.unescape(text).split())) for level, text in page.headings]
        if rendered != headings:
            missing = [h for h in headings if h not in rendered]
            extra = [h for h in rendered if h not in headings]
            problems.append(f"{rel}: the rendered headings are not the source's: missing {missing[:3]}, "
                            f"not in the source {extra[:3]} (a heading swallowed into a code block?)")
        if page.pre != blocks:
            problems.append(f"{rel}: {blocks} code blocks in the source, {page.pre} rendered")
        for link in page.links:
            if not relative(link):
                continue
            links += 1
            target = unquote(urlparse(link).path)
            if not os.path.exists(os.path.normpath(os.path.join(os.path.dirname(path), target))):
                problems.append(f"{rel}: a link to '{link}', which does not exist")
    for p in problems:
        print("FAIL: " + p)
    print(f"{len(files)} Markdown files rendered with cmark-gfm, {links} relative links checked, {len(problems)} problems")
    return 1 if problems else 0


def nav_pages(config_path):
    """The pages the nav of mkdocs.yml lists (a `- Title: page.md` per line)."""
    with open(config_path, encoding="utf-8") as f:
        return re.findall(r"^\s*-\s*[^:]+:\s*(\S+\.md)\s*$", f.read(), re.M)


def check_site(source, site):
    mkdocs = shutil.which("mkdocs")
    if not mkdocs:
        print("mkdocs is not installed (scripts/setup installs it): skipped")
        return SKIP
    config = os.path.join(source, "mkdocs.yml")
    r = subprocess.run([mkdocs, "build", "--strict", "--clean", "-f", config, "--site-dir", site],
                       capture_output=True, text=True)
    if r.returncode != 0:
        print(r.stdout + r.stderr)
        print(f"FAIL: mkdocs build --strict exited with {r.returncode}")
        return 1
    problems = []
    listed = nav_pages(config)
    for path in sorted(glob.glob(os.path.join(source, "docs", "*.md"))):
        if os.path.basename(path) not in listed:
            problems.append(f"docs/{os.path.basename(path)} is not in the nav of mkdocs.yml")
    pages = {}
    for path in glob.glob(os.path.join(site, "**", "*.html"), recursive=True):
        with open(path, encoding="utf-8") as f:
            pages[os.path.normpath(path)] = parse(f.read())
    for page in listed:
        if os.path.normpath(os.path.join(site, page[:-3] + ".html")) not in pages:
            problems.append(f"the nav's {page} was not built")
    links = anchors = 0
    for path, page in sorted(pages.items()):
        rel = os.path.relpath(path, site)
        for remote in page.remote:
            problems.append(f"{rel} loads {remote} from the network")
        for link in page.links:
            if not relative(link) and not link.startswith("#"):
                continue
            u = urlparse(link)
            target = os.path.normpath(os.path.join(os.path.dirname(path), unquote(u.path))) if u.path else path
            links += 1
            if not os.path.exists(target):
                problems.append(f"{rel}: a link to '{link}', which the site does not have")
            elif u.fragment and target in pages:
                anchors += 1
                if u.fragment not in pages[target].ids:
                    problems.append(f"{rel}: a link to '{link}': {os.path.relpath(target, site)} has no anchor '{u.fragment}'")
    for p in problems:
        print("FAIL: " + p)
    print(f"site built with mkdocs --strict into {site}: {len(pages)} pages, {links} links and {anchors} anchors checked, "
          f"{len(problems)} problems")
    return 1 if problems else 0


def main():
    if len(sys.argv) >= 3 and sys.argv[1] == "markdown":
        return check_markdown(os.path.abspath(sys.argv[2]))
    if len(sys.argv) >= 4 and sys.argv[1] == "site":
        return check_site(os.path.abspath(sys.argv[2]), os.path.abspath(sys.argv[3]))
    print(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main())
