"""MkDocs hooks (mkdocs.yml): two pages of the site live outside docs/, each kept in one place:
README.md is the home page (index.md) and bench/RESULTS.md the benchmarks (benchmarks.md).
Their links are written for the repository (README's `docs/reference.md`); every relative
link of every page is rewritten from where its file really is to where the page is on the
site. A link to a file of the repository that is not on the site is left as it is, and
`mkdocs build --strict` fails on it."""
import os
import re

from mkdocs.structure.files import File

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DOCS = os.path.join(ROOT, "docs")
FROM_ELSEWHERE = {"README.md": "index.md", os.path.join("bench", "RESULTS.md"): "benchmarks.md"}
LINK = re.compile(r"(!?\[[^\]]*\]\()([^)\s#]*)(#[^)\s]*)?\)")


def on_files(files, config):
    for source, page in FROM_ELSEWHERE.items():
        f = File(page, ROOT, config["site_dir"], config["use_directory_urls"])
        f.abs_src_path = os.path.join(ROOT, source)
        files.append(f)
    return files


def site_path(real):
    """Where a file of the repository is on the site, or None."""
    if real.startswith(DOCS + os.sep):
        return os.path.relpath(real, DOCS)
    return FROM_ELSEWHERE.get(os.path.relpath(real, ROOT))


def rewrite(line, real_dir, page_dir):
    def one(m):
        target = m.group(2)
        if not target or re.match(r"^[a-z]+:", target) or target.startswith("/"):
            return m.group(0)
        on_site = site_path(os.path.normpath(os.path.join(real_dir, target)))
        if on_site is None:
            return m.group(0)
        return m.group(1) + os.path.relpath(on_site, page_dir) + (m.group(3) or "") + ")"
    return LINK.sub(one, line)


def on_page_markdown(markdown, page, config, files):
    real_dir = os.path.dirname(page.file.abs_src_path)
    page_dir = os.path.dirname(page.file.src_path) or "."
    # Outside fenced code only (a link's text may run over two lines).
    out, chunk, fenced = [], [], False
    for line in markdown.split("\n"):
        if line.lstrip().startswith("```"):
            out.append(rewrite("\n".join(chunk), real_dir, page_dir) if not fenced else "\n".join(chunk))
            chunk, fenced = [], not fenced
            out.append(line)
        else:
            chunk.append(line)
    out.append(rewrite("\n".join(chunk), real_dir, page_dir) if not fenced else "\n".join(chunk))
    return "\n".join(out)
