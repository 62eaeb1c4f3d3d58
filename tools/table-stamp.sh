# What heads every generated table under docs/tables/ (sourced by the table scripts in tools/):
#   table_commit ROOT   the commit checked out in ROOT when the run ends (build the tools from
#                       that tree), with "+ uncommitted changes" when files other than docs/ and
#                       *.md differ from it; "not recorded" outside a git checkout
#   table_cpu           the CPU model and its core count
#   table_load          the load average now (1, 5 and 15 minutes), comma-separated
table_commit() {
    local commit
    commit="$(git -C "$1" rev-parse --short HEAD 2>/dev/null || echo "not recorded")"
    if [ "$commit" != "not recorded" ] && [ -n "$(git -C "$1" status --porcelain -- . ':!docs' ':!*.md' 2>/dev/null)" ]; then
        commit="$commit + uncommitted changes"
    fi
    echo "$commit"
}
table_cpu() { echo "$(awk -F': ' '/model name/ {print $2; exit}' /proc/cpuinfo) ($(nproc) cores)"; }
table_load() { cut -d' ' -f1-3 /proc/loadavg | sed 's/ /, /g'; }
