"""The book builds from scratch with warnings as errors and every cell executed afresh."""

from __future__ import annotations

from conftest import BookBuild


def test_book_builds_with_warnings_as_errors(book_build: BookBuild) -> None:
    assert book_build.returncode == 0, f"book build failed:\n{book_build.log}"
    html = book_build.html
    assert (html / "index.html").is_file()
    assert (html / "notebooks" / "01-what-is-dynamic-amplification.html").is_file()
