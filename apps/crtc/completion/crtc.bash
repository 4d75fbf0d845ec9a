# bash completion for crtc: options, their values, and .crt scripts.
# Installed as share/bash-completion/completions/crtc; or `source` this file.

_crtc() {
    local cur=${COMP_WORDS[COMP_CWORD]}
    local prev=${COMP_WORDS[COMP_CWORD - 1]}
    local IFS=$'\n'
    COMPREPLY=()
    case $prev in
    -o)
        COMPREPLY=($(compgen -f -- "$cur"))
        compopt -o filenames 2>/dev/null
        return
        ;;
    -I | --assets)
        COMPREPLY=($(compgen -d -- "$cur"))
        compopt -o filenames 2>/dev/null
        return
        ;;
    --color)
        COMPREPLY=($(compgen -W $'auto\nalways\nnever' -- "$cur"))
        return
        ;;
    --width | --height | --threads | --fps | --png-compression | --time | --frames | --seed | \
        --max-steps | --max-depth | --max-entities | --max-size)
        return # a number
        ;;
    esac
    if [[ $cur == -* ]]; then
        local options=(
            --check --dump-ast --dump-scene --format
            -o --width --height --threads --fps --png-compression --stats
            -I --assets --time --frames --seed
            --max-steps --max-depth --max-entities --max-size
            -Werror --color -q --quiet -h --help --version
        )
        COMPREPLY=($(compgen -W "${options[*]}" -- "$cur"))
        return
    fi
    # Scripts, and folders to reach them.
    COMPREPLY=($(compgen -d -- "$cur") $(compgen -f -X '!*.crt' -- "$cur"))
    compopt -o filenames 2>/dev/null
}
complete -F _crtc crtc
