#!/usr/bin/env bash
# The parameter reference, docs/parameters.md, made from the tools themselves:
# every entry of `micro template`, `micro template --sweep`, `micro template
# --oscillation`, `micro template --slip` and `macro template`
# (one table a subsection: default, allowed values, documentation, in the
# templates' own words) and the `--help` of micro, bridge, macro and each of
# their subcommands (found in the tools' own list of subcommands).
#   scripts/parameter_reference.sh build > docs/parameters.md
# BUILD_DIR holds micro/micro, bridge/bridge and macro/macro; the variables
# SOFTGLASS_MICRO, SOFTGLASS_BRIDGE and SOFTGLASS_MACRO name other executables.
# Prints nothing and fails when a template is not in the shape it
# parses, so that the page never holds half a table.
set -euo pipefail
shopt -s inherit_errexit
export LC_ALL=C

if [ $# -ne 1 ]; then
  echo "usage: $0 BUILD_DIR > docs/parameters.md" >&2
  exit 2
fi
build=$1
declare -A tool=(
  [micro]=${SOFTGLASS_MICRO:-$build/micro/micro}
  [bridge]=${SOFTGLASS_BRIDGE:-$build/bridge/bridge}
  [macro]=${SOFTGLASS_MACRO:-$build/macro/macro}
)
for name in micro bridge macro; do
  [ -x "${tool[$name]}" ] || { echo "$0: no executable ${tool[$name]}" >&2; exit 2; }
done

# A deal.II PRM listing (as `print_parameters(PRM)` writes it, after optional
# opening comments) as tab-separated records:
#   note  TAB text                                  an opening comment line
#   entry TAB subsection TAB name TAB default TAB allowed TAB documentation
# `subsection` is the path a/b of nested subsections, empty at the top level;
# `allowed` is what follows the documentation's last " Allowed: " (micro's
# templates append their patterns so), empty where there is none.
parse_prm() {  # label < listing
  awk -v label="$1" '
    function fail(why) {
      printf "parameter_reference.sh: %s, line %d: %s: [%s]\n", label, NR, why, $0 > "/dev/stderr"
      failed = 1
      exit 1
    }
    function trim(s) { sub(/^ +/, "", s); sub(/ +$/, "", s); return s }
    /\t/ { fail("a tab") }
    !listing && /^# Listing of Parameters$/ { listing = 1; next }
    !listing && /^#/ { line = $0; sub(/^# ?/, "", line); print "note\t" line; next }
    !listing { fail("a line before the listing") }
    listing == 1 && /^# -+$/ { listing = 2; next }
    /^ *$/ { if (doc != "") fail("documentation without an entry"); next }
    /^ *#/ { line = $0; sub(/^ *# ?/, "", line); doc = doc == "" ? line : doc " " line; next }
    /^ *subsection / {
      if (doc != "") fail("documentation before a subsection")
      name = trim(substr($0, index($0, "subsection ") + 11))
      path[++depth] = name
      next
    }
    /^ *end *$/ {
      if (depth == 0) fail("end without subsection")
      depth--
      next
    }
    /^ *set / {
      line = substr($0, index($0, "set ") + 4)
      eq = index(line, "=")
      if (eq == 0) fail("set without =")
      name = trim(substr(line, 1, eq - 1))
      value = trim(substr(line, eq + 1))
      if (value ~ /# default:/) fail("a value other than the default")
      if (value ~ /\\$/) fail("a continued line")
      sub_path = ""
      for (i = 1; i <= depth; i++) sub_path = sub_path == "" ? path[i] : sub_path "/" path[i]
      allowed = ""
      text = doc
      if (text ~ /^Allowed: /) {
        allowed = substr(text, 10)
        text = ""
      } else {
        at = 0
        rest = text
        while ((j = index(rest, " Allowed: ")) > 0) { at += j; rest = substr(rest, j + 1) }
        if (at > 0) { allowed = substr(text, at + 10); text = substr(text, 1, at - 1) }
      }
      print "entry\t" sub_path "\t" name "\t" value "\t" allowed "\t" text
      entries++
      doc = ""
      next
    }
    { fail("a line of no known kind") }
    END {
      if (failed) exit 1
      if (listing != 2) { printf "parameter_reference.sh: %s: no \"# Listing of Parameters\"\n", label > "/dev/stderr"; exit 1 }
      if (depth != 0) { printf "parameter_reference.sh: %s: subsection without end\n", label > "/dev/stderr"; exit 1 }
      if (doc != "") { printf "parameter_reference.sh: %s: documentation without an entry at the end\n", label > "/dev/stderr"; exit 1 }
      if (entries == 0) { printf "parameter_reference.sh: %s: no entries\n", label > "/dev/stderr"; exit 1 }
    }'
}

# The subsections of parsed records, in order of first appearance (one a line;
# an empty line for the top level).
subsections() { awk -F'\t' '$1 == "entry" && !seen[$2]++ { print $2 }'; }

# The entries of one subsection of parsed records, as a markdown table; the
# column "Allowed" only where an entry has allowed values.
table() {  # subsection < records
  awk -F'\t' -v want="$1" '
    function text(s) {  # prose in a table cell: nothing markdown would read as markup
      gsub(/\\/, "\\\\", s); gsub(/\|/, "\\|", s); gsub(/\*/, "\\*", s); gsub(/~/, "\\~", s)
      return no_tags(s)
    }
    function no_tags(s,  out) {  # "<" before a letter, /, ! or ? would open HTML
      while (match(s, /<[A-Za-z\/!?]/)) { out = out substr(s, 1, RSTART - 1) "\\<"; s = substr(s, RSTART + 1) }
      return out s
    }
    function code(s) {  # a value as a code span
      if (s == "") return "(empty)"
      gsub(/\|/, "\\|", s)
      return index(s, "`") ? "`` " s " ``" : "`" s "`"
    }
    $1 == "entry" && $2 == want {
      n++; name[n] = $3; value[n] = $4; allowed[n] = $5; doc[n] = $6
      if ($5 != "") with_allowed = 1
    }
    END {
      if (with_allowed) {
        print "| Entry | Default | Allowed | Documentation |"
        print "|---|---|---|---|"
      } else {
        print "| Entry | Default | Documentation |"
        print "|---|---|---|"
      }
      for (i = 1; i <= n; i++) {
        row = "| " code(name[i]) " | " code(value[i])
        if (with_allowed) row = row " | " text(allowed[i])
        print row " | " text(doc[i]) " |"
      }
    }'
}


subsection_heading() {  # prefix subsection
  if [ -z "$2" ]; then echo "### $1: top level"; else echo "### $1: subsection \`$2\`"; fi
}

# A GitHub heading anchor: lower case, only letters, digits, blanks, - and _
# kept, blanks made -.
slug() { tr '[:upper:]' '[:lower:]' | sed -e 's/[^a-z0-9 _-]//g' -e 's/ /-/g'; }

# The entry records of one subsection.
entries_of() { awk -F'\t' -v want="$1" '$1 == "entry" && $2 == want'; }

# Whether a subsection has the same entries in two sets of parsed records.
same_subsection() {  # subsection records other-records
  [ "$(entries_of "$1" <<<"$2")" = "$(entries_of "$1" <<<"$3")" ]
}

# One section of the page: a parameter file, a table a subsection. Subsections
# whose records are those of the same subsection in `reference` (records of
# another file) are named, with a link, instead of repeated.
parameter_file() {  # heading prefix command records [reference-prefix reference-records]
  local heading=$1 prefix=$2 command=$3 records=$4 reference_prefix=${5:-} reference=${6:-}
  local same=() s
  echo "## $heading"
  echo
  if grep -q '^note' <<<"$records"; then
    echo "Printed by \`$command\`, which opens with:"
    echo
    grep '^note' <<<"$records" | cut -f2- | sed -e 's/\*/\\*/g' -e 's/<\([A-Za-z/!?]\)/\\<\1/g' -e 's/^/> /'
  else
    echo "Printed by \`$command\`."
  fi
  echo
  while IFS= read -r s; do
    if [ -n "$reference" ] && same_subsection "$s" "$records" "$reference"; then
      same+=("[\`$s\`](#$(subsection_heading "$reference_prefix" "$s" | sed 's/^### //' | slug))")
    fi
  done < <(subsections <<<"$records")
  if [ ${#same[@]} -gt 0 ]; then
    local list=${same[0]} i
    for ((i = 1; i < ${#same[@]}; i++)); do list+=", ${same[i]}"; done
    echo "Subsections as in the ${reference_prefix} parameter file: $list."
    echo
  fi
  while IFS= read -r s; do
    [ -n "$reference" ] && same_subsection "$s" "$records" "$reference" && continue
    subsection_heading "$prefix" "$s"
    echo
    table "$s" <<<"$records"
    echo
  done < <(subsections <<<"$records")
}

# The subcommands a CLI11 `--help` lists under "Subcommands:".
subcommands() {
  awk '/^Subcommands:$/ { on = 1; next } on && /^  [^ ]/ { print $1 } on && /^[^ ]/ { on = 0 }'
}

help_block() {  # heading text
  echo "### $1"
  echo
  echo '```text'
  printf '%s\n' "$2"
  echo '```'
  echo
}

command_line() {
  local name sub help commands
  echo "## Command-line options"
  echo
  echo "The \`--help\` of each tool and of each of its subcommands."
  echo
  for name in micro bridge macro; do
    help=$("${tool[$name]}" --help)
    commands=$(subcommands <<<"$help")
    [ -n "$commands" ] || { echo "$0: $name --help lists no subcommands" >&2; exit 1; }
    help_block "\`$name\`" "$help"
    for sub in $commands; do
      help=$("${tool[$name]}" "$sub" --help)
      help_block "\`$name $sub\`" "$help"
    done
  done
}

template=$("${tool[micro]}" template)
micro_run=$(parse_prm "micro template" <<<"$template")
template=$("${tool[micro]}" template --sweep)
micro_sweep=$(parse_prm "micro template --sweep" <<<"$template")
template=$("${tool[micro]}" template --oscillation)
micro_oscillation=$(parse_prm "micro template --oscillation" <<<"$template")
template=$("${tool[micro]}" template --slip)
micro_slip=$(parse_prm "micro template --slip" <<<"$template")
template=$("${tool[macro]}" template)
macro_scene=$(parse_prm "macro template" <<<"$template")

body=$(
  parameter_file "micro parameter file" micro "micro template" "$micro_run"
  parameter_file "micro sweep file" "micro sweep" "micro template --sweep" "$micro_sweep" \
    micro "$micro_run"
  parameter_file "micro oscillation file" "micro oscillate" "micro template --oscillation" \
    "$micro_oscillation" micro "$micro_run"
  parameter_file "micro slip file" "micro slip" "micro template --slip" "$micro_slip" \
    micro "$micro_run"
  parameter_file "macro scene file" macro "macro template" "$macro_scene"
  command_line
)

# Headings must be unique: their anchors are the table of contents' links.
duplicates=$(grep -E '^##+ ' <<<"$body" | sed -E 's/^#+ //' | slug | sort | uniq -d)
if [ -n "$duplicates" ]; then
  echo "$0: headings with the same anchor: $duplicates" >&2
  exit 1
fi

page=$(
  echo "Generated by \`scripts/parameter_reference.sh build > docs/parameters.md\` from the"
  echo "tools themselves: do not edit it by hand (tests/common/parameter_reference_test.cpp"
  echo "checks that it is current)."
  echo
  echo "# Parameter reference"
  echo
  echo "Every entry of the parameter files of \`micro\` and \`macro\`, with its default,"
  echo "allowed values and documentation, and every command-line option of \`micro\`,"
  echo "\`bridge\` and \`macro\`. The [user guide](user-guide.md) explains how they are used."
  echo
  echo "## Contents"
  echo
  grep -E '^##+ ' <<<"$body" | while IFS= read -r line; do
    title=${line#* }
    indent=""
    [[ $line == '### '* ]] && indent="  "
    echo "$indent- [${title}](#$(slug <<<"$title"))"
  done
  echo
  printf '%s\n' "$body"
)

# Nothing of this machine: no path of the build or of the home folder.
for word in "$(cd "$build" && pwd)" "${HOME:-}"; do
  if [ ${#word} -gt 1 ] && grep -qF "$word" <<<"$page"; then
    echo "$0: the page holds the machine-dependent path $word" >&2
    exit 1
  fi
done
printf '%s\n' "$page"
