# bash completion for crtc: options, their values, and .crt scripts.
# Installed as share/bash-completion/completions/crtc; or `source` this file.
#
# The options are read from the --help of the crtc being completed, so that this file never
# lists them: every word of the help starting with - or --, and, from the lines that name
# options, which of them take a value (those followed by a placeholder such as N or FILE).

# Fills _crtc_options and _crtc_valued from `program --help`, once per program.
_crtc_read_help() {
    local program=$1 help line spec word names valued IFS=$' \t\n'
    [[ ${_crtc_help_of-} == "$program" ]] && return
    help=$("$program" --help 2>/dev/null) || return
    _crtc_help_of=$program
    _crtc_options=($(grep -oE -- '(^|[][[:space:],(|])--?[A-Za-z][A-Za-z0-9-]*' <<<"$help" |
        sed -E 's/^[][[:space:],(|]//' | sort -u))
    _crtc_valued=()
    while IFS= read -r line; do
        # "  -o,--output FILE   output image", "  --width N, --height N  override ..."
        [[ $line =~ ^[[:space:]]+(-[^[:space:]]*([[:space:]][^[:space:]]+)*) ]] || continue
        spec=${BASH_REMATCH[1]%%  *}
        names=() valued=false
        for word in ${spec//,/ }; do
            if [[ $word == -* ]]; then
                names+=("${word%%=*}")
            elif [[ $word =~ ^[A-Z][A-Z0-9:_]*$ ]]; then
                valued=true
            fi
        done
        $valued && _crtc_valued+=("${names[@]}")
    done <<<"$help"
}

_crtc() {
    local cur=${COMP_WORDS[COMP_CWORD]}
    local prev=${COMP_WORDS[COMP_CWORD - 1]}
    local program=${COMP_WORDS[0]/#\~/$HOME}
    local IFS=$'\n'
    COMPREPLY=()
    type -P "$program" >/dev/null || return
    _crtc_read_help "$(type -P "$program")"
    case $prev in
    -o | --output)
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
    esac
    local option
    for option in "${_crtc_valued[@]}"; do
        [[ $prev == "$option" ]] && return # a number or the like: nothing to offer
    done
    if [[ $cur == -* ]]; then
        COMPREPLY=($(compgen -W "${_crtc_options[*]}" -- "$cur"))
        return
    fi
    # Scripts, and folders to reach them.
    COMPREPLY=($(compgen -d -- "$cur") $(compgen -f -X '!*.crt' -- "$cur"))
    compopt -o filenames 2>/dev/null
}
complete -F _crtc crtc
