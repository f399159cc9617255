#!/usr/bin/env bash
# The documentation's links: every relative link and image in README.md and docs/**/*.md
# points to a file that exists (an image: a non-empty one), and a link to #anchor points to a
# heading of that file (GitHub's slugs: lower case, punctuation dropped, spaces to hyphens, a
# repeated heading gets -1, -2, …). Links inside code are not links; http(s) links are not
# checked. The README must show at least one picture.
# Usage: tests/docs/check_links.sh [SOURCE_DIR]
set -uo pipefail
export LC_ALL=C.UTF-8
root=${1:-$(cd "$(dirname "$0")/../.." && pwd)}
cd "$root" || exit 2

failures=0
fail() { echo "$1: $2" >&2; failures=$((failures + 1)); }

# The file without fenced code blocks and inline code spans, so that `[[x, y], …](…)`-like
# text in code is not read as a link.
prose() {
  awk '/^[ \t]*```/ { code = !code; next } !code' "$1" | sed 's/`[^`]*`//g'
}

# The anchors of a Markdown file's headings, one per line.
anchors() {
  awk '/^[ \t]*```/ { code = !code; next } !code && /^#+ / { sub(/^#+ +/, ""); print }' "$1" |
    sed -e 's/\[\([^]]*\)\]([^)]*)/\1/g' -e 's/.*/\L&/' -e 's/[^[:alnum:] _-]//g' -e 's/ /-/g' |
    awk '{ n = seen[$0]++; print (n ? $0 "-" n : $0) }'
}

# Every link target in a file: [text](target), ![alt](target), src="target", href="target".
targets() {
  prose "$1" | grep -oE '\]\([^) ]+\)|(src|href)="[^"]+"' |
    sed -E -e 's/^\]\((.*)\)$/\1/' -e 's/^(src|href)="(.*)"$/\2/'
}

files=(README.md)
while IFS= read -r f; do files+=("$f"); done < <(find docs -name '*.md' | sort)

checked=0
for file in "${files[@]}"; do
  dir=$(dirname "$file")
  while IFS= read -r target; do
    case "$target" in
      http://* | https://* | mailto:*) continue ;;
    esac
    checked=$((checked + 1))
    path=${target%%#*}
    anchor=
    [[ "$target" == *"#"* ]] && anchor=${target#*#}
    if [[ -z "$path" ]]; then
      resolved=$file
    else
      resolved="$dir/$path"
      if [[ ! -e "$resolved" ]]; then
        fail "$file" "links to $target, which does not exist ($resolved)"
        continue
      fi
      case "$path" in
        *.png | *.jpg | *.jpeg | *.gif | *.svg)
          [[ -s "$resolved" ]] || fail "$file" "shows $target, which is empty" ;;
      esac
    fi
    if [[ -n "$anchor" ]]; then
      if [[ "$resolved" != *.md ]]; then
        fail "$file" "links to an anchor in $target, which is not a Markdown file"
      elif ! anchors "$resolved" | grep -qxF -- "$anchor"; then
        fail "$file" "links to $target, but $resolved has no heading #$anchor"
      fi
    fi
  done < <(targets "$file")
done

images=$(targets README.md | grep -cE '\.(png|jpg|jpeg|gif|svg)$')
((images > 0)) || fail README.md "shows no picture"

if ((failures > 0)); then
  echo "$failures broken link(s) in ${#files[@]} files" >&2
  exit 1
fi
echo "${#files[@]} files, $checked relative links and $images README pictures: all resolve"
