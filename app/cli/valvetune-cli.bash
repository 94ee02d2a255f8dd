# bash completion for valvetune-cli: its commands, each command's options and the values of the
# options that take a fixed set of them (installed as
# /usr/share/bash-completion/completions/valvetune-cli). The commands and options are the ones
# valvetune-cli --help and COMMAND --help print; tests/packaging/check_completion.sh keeps them
# equal.

_valvetune_cli_families()
{
    # The first word of each line of `valvetune-cli dictionary list` is a family id.
    valvetune-cli dictionary list 2>/dev/null | awk '/^[a-z][a-z0-9-]* / { print $1 }'
}

_valvetune_cli()
{
    local cur=${COMP_WORDS[COMP_CWORD]}
    local prev=${COMP_WORDS[COMP_CWORD - 1]}
    local commands="decode encode dictionary info scan read get set write diff monitor test report reference fold"
    local connection="--sim --factory --port --baud --parity --stop --tcp --protocol --can --node --hart
        --unit --out-register --in-register --in-function --register-bytes --pzd-words --ind-byte
        --module --fault --product --turnaround --no-silent-interval --frame-end --lang --json
        --help"

    # The values of options that take one of a known set; a path for those that take a file.
    case $prev in
        --port | --hart | --out | --file | --reference | --run)
            mapfile -t COMPREPLY < <(compgen -f -- "$cur")
            return
            ;;
        --audit-dir)
            mapfile -t COMPREPLY < <(compgen -d -- "$cur")
            return
            ;;
        --sim | --dictionary)
            mapfile -t COMPREPLY < <(compgen -W "$(_valvetune_cli_families)" -- "$cur")
            return
            ;;
        --parity) mapfile -t COMPREPLY < <(compgen -W "none even odd" -- "$cur") && return ;;
        --stop) mapfile -t COMPREPLY < <(compgen -W "1 2" -- "$cur") && return ;;
        --frame-end) mapfile -t COMPREPLY < <(compgen -W "silence crc" -- "$cur") && return ;;
        --lang) mapfile -t COMPREPLY < <(compgen -W "en de" -- "$cur") && return ;;
        --direction) mapfile -t COMPREPLY < <(compgen -W "request response" -- "$cur") && return ;;
        --in-function) mapfile -t COMPREPLY < <(compgen -W "3 4" -- "$cur") && return ;;
        --ind-byte) mapfile -t COMPREPLY < <(compgen -W "2 3" -- "$cur") && return ;;
        --register-bytes | --pzd-words)
            mapfile -t COMPREPLY < <(compgen -W "high-first low-first" -- "$cur")
            return
            ;;
        --node)
            # fold plan takes a node type; the device commands a CANopen node id (a number).
            [[ " ${COMP_WORDS[*]} " == *" fold "* ]] &&
                mapfile -t COMPREPLY < <(compgen -W "opat dma-pb dma-pn" -- "$cur")
            return
            ;;
        --product)
            [[ " ${COMP_WORDS[*]} " == *" fold "* ]] ||
                mapfile -t COMPREPLY < <(compgen -W "opat dma-pn dma-pb ed1" -- "$cur")
            return
            ;;
        --baud | --tcp | --can | --unit | --module | --fault | --turnaround | --timeout | \
            --rate | --duration | --tadr | --sadr | --id | --count | --value | --cob-id | \
            --profile | --modules | --out-register | --in-register | --customer | --machine | \
            --axis | --operator | --comment)
            return
            ;;
    esac

    # The command is the first word that is no option (nor --audit-dir's directory).
    local i command=
    for ((i = 1; i < COMP_CWORD; i++)); do
        if [[ ${COMP_WORDS[i]} == --audit-dir ]]; then
            i=$((i + 1))
        elif [[ ${COMP_WORDS[i]} != -* ]]; then
            command=${COMP_WORDS[i]}
            break
        fi
    done
    if [[ -z $command ]]; then
        if [[ $cur == -* ]]; then
            mapfile -t COMPREPLY < <(compgen -W "--json --audit-dir --help --version" -- "$cur")
        else
            mapfile -t COMPREPLY < <(compgen -W "$commands" -- "$cur")
        fi
        return
    fi

    local options words= files=
    case $command in
        decode)
            options="--protocol --family --direction --profile --dictionary --cob-id --lang --json
                --help"
            [[ $prev == --protocol ]] &&
                words="gateway modbus-rtu modbus-tcp profidrive pkw pzd hart canopen"
            ;;
        encode)
            options="--tadr --sadr --id --count --value --family --module --unit --json --help"
            case $((COMP_CWORD - i)) in
                1) words="gateway modbus-rtu" ;;
                2) [[ ${COMP_WORDS[i + 1]} == gateway ]] && words="read write cyclic" ||
                    words="read write" ;;
            esac
            ;;
        dictionary)
            options="--lang --json --help"
            case $((COMP_CWORD - i)) in
                1) words="list show" ;;
                2) [[ ${COMP_WORDS[i + 1]} == show ]] && words=$(_valvetune_cli_families) ;;
            esac
            ;;
        fold)
            options="--node --modules --product --lang --json --help"
            [[ $((COMP_CWORD - i)) -eq 1 ]] && words="plan"
            ;;
        info | get) options=$connection ;;
        scan) options="$connection --timeout" ;;
        read) options="$connection --out" ;;
        set) options="$connection --yes" ;;
        write) options="$connection --dry-run --yes" files=vtpar ;;
        diff) options=$connection files=vtpar ;;
        monitor) options="$connection --rate --duration --csv" ;;
        test)
            options="$connection --yes --branch --rate --window --csv --from --to --hold --repeat \
--direction --amplitude --offset --frequency --cycles --settling --from-hz --to-hz \
--points-per-decade"
            [[ $((COMP_CWORD - i)) -eq 1 ]] && words="step square triangle sine sweep"
            [[ $prev == --direction ]] && words="up down both"
            ;;
        report)
            options="$connection --out --file --reference --run --session-log --customer --machine \
--axis --operator --comment"
            ;;
        reference)
            options="$connection --yes --rate --window --out --centre --amplitude --hold --sweep \
--from-hz --to-hz --points-per-decade --branch --rise-time --overshoot --settling --steady-state \
--bandwidth --phase-90"
            [[ $((COMP_CWORD - i)) -eq 1 ]] && words="save compare"
            [[ $((COMP_CWORD - i)) -eq 2 && $prev == compare ]] && files=vtref
            ;;
        *) return ;;
    esac
    if [[ $prev == --protocol && $command != decode ]]; then
        local links="modbus-rtu modbus-tcp node-image dsp408-image dsp408-gateway"
        mapfile -t COMPREPLY < <(compgen -W "$links" -- "$cur")
    elif [[ $cur == -* ]]; then
        mapfile -t COMPREPLY < <(compgen -W "$options" -- "$cur")
    elif [[ -n $files ]]; then
        # A parameter file, or a folder on the way to one.
        mapfile -t COMPREPLY < <(compgen -f -X "!*.$files" -- "$cur"; compgen -d -- "$cur")
    else
        mapfile -t COMPREPLY < <(compgen -W "$words" -- "$cur")
    fi
}
complete -F _valvetune_cli valvetune-cli
