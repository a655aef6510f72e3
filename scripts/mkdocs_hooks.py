"""MkDocs hooks (mkdocs.yml `hooks:`): the site ships the pages and what they show, not the
scripts that keep them honest.

docs/ holds the pages' generators and checks beside the pages (gen_commands.py,
check_figures.py, gen_scene_reference.cpp, …), and MkDocs copies every file of docs_dir into
the site; `exclude_docs` came in MkDocs 1.5, after Debian 12's 1.4. Of the files from docs/ the
site keeps those of the kinds below; the theme's own files are left as they are. A page that
links to a file dropped here fails the strict build (a broken link), so nothing goes missing in
silence. The test Docs.SiteWorksOfflineAndShipsNoScripts checks the built site.
"""

import os

# What a page is or shows: Markdown, pictures, videos, styles and scripts the pages load.
SHIPPED = {".md", ".png", ".jpg", ".jpeg", ".gif", ".svg", ".webp", ".mp4", ".webm", ".css", ".js"}


def on_files(files, config):
    docs = os.path.realpath(config["docs_dir"]) + os.sep
    for file in list(files):
        source = os.path.realpath(file.abs_src_path)
        if source.startswith(docs) and os.path.splitext(source)[1].lower() not in SHIPPED:
            files.remove(file)
    return files
