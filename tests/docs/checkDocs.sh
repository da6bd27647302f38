#!/usr/bin/env bash
# Keeps the documentation a reference (docs/README: "Docs state the current truth"):
#  1. no dated narrative: no date (20YY-MM-DD) and none of "this session", "today",
#     "yesterday", "this evening" in README.md or docs/**/*.md (history belongs in
#     CHANGELOG.md, which is not checked);
#  2. no dead relative links: every [text](target) and ![alt](target) of those files that
#     is not a URL or an anchor names a file or directory that exists.
# Prints every offence as file:line: what, and exits 1 if there is any.
# Usage: checkDocs.sh [<source dir>]   (default: $ROCKFRAC_SOURCE_DIR, else two levels up)
set -u
root=${1:-${ROCKFRAC_SOURCE_DIR:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}}
cd "$root" || { echo "checkDocs: cannot enter $root" >&2; exit 1; }

files=(README.md)
while IFS= read -r f; do files+=("$f"); done < <(find docs -name '*.md' ! -name CHANGELOG.md | sort)

status=0

# 1. Dates and dated words.
if grep -nHE '20[0-9]{2}-[0-9]{2}-[0-9]{2}' "${files[@]}" | sed 's/^\([^:]*:[0-9]*\):.*/\1: a date (history goes to CHANGELOG.md)/' | grep .; then
    status=1
fi
if grep -nHiwE 'this session|today|yesterday|this evening' "${files[@]}" |
    sed 's/^\([^:]*:[0-9]*\):.*/\1: dated wording (this session, today, yesterday, this evening)/' | grep .; then
    status=1
fi

# 2. Relative links, outside fenced code blocks: file<TAB>line<TAB>target.
while IFS=$'\t' read -r file line target; do
    target=${target%% *}          # drop a "title"
    target=${target%%#*}          # drop an #anchor
    [ -z "$target" ] && continue
    case $target in
        http://* | https://* | mailto:* | ftp://*) continue ;;
    esac
    if [[ $target == /* ]]; then path=$target; else path=$(dirname "$file")/$target; fi
    if [ ! -e "$path" ]; then
        echo "$file:$line: link to '$target', which does not exist"
        status=1
    fi
done < <(awk '
    FNR == 1 { fence = 0 }
    /^[ \t]*(```|~~~)/ { fence = !fence; next }
    fence { next }
    {
        s = $0
        gsub(/`[^`]*`/, "", s)    # code spans hold no links
        while (match(s, /\]\([^)]+\)/)) {
            printf "%s\t%d\t%s\n", FILENAME, FNR, substr(s, RSTART + 2, RLENGTH - 3)
            s = substr(s, RSTART + RLENGTH)
        }
    }' "${files[@]}")

if [ $status -eq 0 ]; then
    echo "checkDocs: ${#files[@]} files, no date, no dated wording, every relative link resolves"
fi
exit $status
