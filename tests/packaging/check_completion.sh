#!/usr/bin/env bash
# valvetune-cli's bash completion against the program itself: after "valvetune-cli " it offers
# exactly the commands --help lists, after "valvetune-cli --" every global option, and after
# "valvetune-cli COMMAND --" every option that the command's --help names.
#   check_completion.sh VALVETUNE_CLI COMPLETION_FILE
set -euo pipefail
cli=$1 completion=$2
PATH="$(dirname "$cli"):$PATH"
# shellcheck source=/dev/null
source "$completion"

# The words offered for the command line "$@" (the last word is the one being completed).
offered() {
    set +e # the completion runs in an interactive shell, where a failing test is no error
    COMP_WORDS=("$@")
    COMP_CWORD=$(($# - 1))
    COMP_LINE="$*"
    COMP_POINT=${#COMP_LINE}
    COMPREPLY=()
    _valvetune_cli valvetune-cli "${COMP_WORDS[COMP_CWORD]}" "${COMP_WORDS[COMP_CWORD - 1]}"
    printf '%s\n' "${COMPREPLY[@]}" | sort -u
}
options_in() { grep -o -- '--[a-z][a-z0-9-]*' | sort -u; }

problems=()
commands=$("$cli" --help | sed -n '/^Commands:/,/^$/s/^  \([a-z][a-z0-9-]*\) .*/\1/p' | sort -u)
[[ -n $commands ]] || { echo "check_completion: $cli --help lists no commands" >&2; exit 1; }
[[ $(offered valvetune-cli "") == "$commands" ]] ||
    problems+=("commands offered: $(offered valvetune-cli "" | tr '\n' ' '), --help: $(tr '\n' ' ' <<<"$commands")")

global=$(offered valvetune-cli --)
for option in $("$cli" --help | sed -n '/^Options:/,/^$/p' | options_in); do
    grep -qx -- "$option" <<<"$global" || problems+=("valvetune-cli $option")
done
count=0
for command in $commands; do
    mine=$(offered valvetune-cli "$command" --)
    for option in $("$cli" "$command" --help | options_in); do
        count=$((count + 1))
        grep -qx -- "$option" <<<"$mine" || problems+=("valvetune-cli $command $option")
    done
done

if [[ ${#problems[@]} -gt 0 ]]; then
    echo "check_completion: $completion does not offer what valvetune-cli --help says:" >&2
    printf '  %s\n' "${problems[@]}" >&2
    exit 1
fi
echo "check_completion: $(wc -w <<<"$commands") commands and $count command options offered"
