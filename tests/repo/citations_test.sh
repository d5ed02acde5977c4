#!/usr/bin/env bash
# Citations stay inside the repository. A comment or a document may cite the repository's own
# docs (docs/..., a model's README), a paper (with its section) or a standard; it may not send
# a newcomer to material the repository does not hold: the reference folder next to it, its
# design and style notes, notes on the study's code, or issue numbers
# (docs/conventions.md "Comments and citations").
#
# Scanned: every tracked source file (C++, CMake, shell, Python, configuration) and every
# Markdown file except CHANGELOG.md, a history of what happened rather than a citation. In
# source files the ban on issue numbers and on the reference folder applies to the comment part
# of a line (after // or #), so that code may still read the measured skies from the
# reference folder at run time; the names of the design, style and implementation notes are
# refused anywhere. The data path of the measured skies, ../shared/data/kider2014, is data, not
# a citation, and stays allowed where a document says where the data is read from.
#
# Usage: citations_test.sh [SOURCE_DIR]   (default: the repository holding this script)
# Before scanning, the script checks itself on a scratch tree with one planted citation of each
# kind, so that a broken pattern cannot pass silently.
set -euo pipefail

self_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="${1:-$(cd "$self_dir/../.." && pwd)}"

# The files to scan, relative to $1: tracked files in a git checkout, otherwise every file
# outside build trees, the local database and hidden folders.
list_files() {
  if git -C "$1" rev-parse --is-inside-work-tree > /dev/null 2>&1; then
    git -C "$1" ls-files
  else
    (cd "$1" && find . -type f -not -path './build*' -not -path './var/*' -not -path './.*' \
      | sed 's|^\./||')
  fi
}

# How a file's comments are written: slash (C++), hash (CMake, shell, ...), md, or skip.
kind_of() {
  local path="$1" full="$2"
  case "$path" in
    CHANGELOG.md | */CHANGELOG.md) echo skip ;;
    *.md) echo md ;;
    *.cpp | *.cc | *.h | *.hpp | *.c | *.js | *.css) echo slash ;;
    *CMakeLists.txt | *.cmake | *.sh | *.py | *.toml | *.yml | *.yaml | *.conf | *.service | \
      *.clang-format | *.gitignore | *Dockerfile) echo hash ;;
    *.*) echo skip ;;
    *)
      # Extension-less scripts such as .ci/run.
      if head -c 2 "$full" 2> /dev/null | grep -q '^#!'; then echo hash; else echo skip; fi
      ;;
  esac
}

# Prints "path:line: text" for each offending line of the files under $1; returns 1 if any.
scan() {
  local dir="$1" found=0 path kind
  while IFS= read -r path; do
    [ -f "$dir/$path" ] || continue
    kind="$(kind_of "$path" "$dir/$path")"
    [ "$kind" = skip ] && continue
    if ! awk -v kind="$kind" -v path="$path" '
      {
        line = $0
        if (kind == "md") {
          part = line
          gsub(/\]\(#[^)]*\)/, "", part)               # anchors of Markdown links
        } else if (kind == "slash") {
          part = ""
          if (match(line, /\/\/|\/\*/)) part = substr(line, RSTART)
          else if (line ~ /^[ \t]*\*/) part = line       # inside a /* ... */ block
        } else {
          part = ""
          if (match(line, /(^|[ \t])#/)) part = substr(line, RSTART)
        }
        gsub(/\.\.\/shared\/data\/kider2014/, "", part)  # the data path of the measured skies
        bad = ""
        if (line ~ /DESIGN\.md|STYLE\.md|IMPLEMENTATION[-]NOTES/) bad = "design, style or implementation notes"
        else if (part ~ /\.\.\/shared|(^|[^[:alnum:]_])shared\/(data|paper|tools|hooks)/) bad = "the reference folder (../shared)"
        else if (part ~ /[Ii]ssues?[ \t]+#?[0-9]/) bad = "an issue number"
        else if (part ~ /(^|[^&[:alnum:]_#])#[0-9]+([^[:alnum:]_]|$)/) bad = "an issue number"
        if (bad != "") {
          printf "%s:%d: cites %s: %s\n", path, FNR, bad, line
          status = 1
        }
      }
      END { exit status }' "$dir/$path"; then
      found=1
    fi
  done < <(list_files "$dir")
  return "$found"
}

# Self-check: each planted citation is found, and the allowed uses are not flagged.
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
notes="IMPLEMENTATION""-NOTES"
design="DESIGN"".md"
style="STYLE"".md"
reference="../""shared"
planted=(
  "a.h|// as ${design} \"Layout\" says"
  "b.cpp|int x = 0;  // ${style} habit 3"
  "c.h|// the study's grid (${notes} \"Evaluation\")"
  "d.h|// layout in ${reference}/data/README.md"
  "e.cpp|// see issue"" 9"
  "f.cmake|# fixed in #""12"
  "g.sh|echo hi  # ${reference}/paper"
  "h.md|As ${design} fixes it."
  "i.md|(Issue"" 5)"
  "j.cpp|const char* help = \"as ${design} says\";"
)
for entry in "${planted[@]}"; do
  rm -rf "$scratch/tree" && mkdir -p "$scratch/tree"
  printf '%s\n' "${entry#*|}" > "$scratch/tree/${entry%%|*}"
  if scan "$scratch/tree" > /dev/null; then
    echo "citations_test.sh: self-check failed, not flagged: ${entry#*|}" >&2
    exit 2
  fi
done
rm -rf "$scratch/tree" && mkdir -p "$scratch/tree"
{
  printf 'set(DATA "${PROJECT_SOURCE_DIR}/%s/data" CACHE PATH "The measurement data")\n' "$reference"
  printf 'if [ ! -d %s/data/kider2014 ]; then echo "${#missing[@]}"; fi\n' "$reference"
} > "$scratch/tree/CMakeLists.txt"
printf 'Read from `%s/data/kider2014`; see [the layers](#1-layers).\n' "$reference" \
  > "$scratch/tree/README.md"
printf '#include <vector>\n// shared_ptr, shared/exclusive locks, the shared machine\n' \
  > "$scratch/tree/k.h"
if ! scan "$scratch/tree"; then
  echo "citations_test.sh: self-check failed, an allowed use was flagged" >&2
  exit 2
fi

if scan "$root"; then
  echo "citations_test.sh: no citation outside the repository"
else
  echo "citations_test.sh: cite docs/..., a model's README, the paper (with its section) or a" \
    "standard instead (docs/conventions.md \"Comments and citations\")" >&2
  exit 1
fi
