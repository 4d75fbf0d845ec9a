;;; crt-mode.el --- Major mode for CRT scene scripts -*- lexical-binding: t -*-

;; Version: 0.1.0
;; Package-Requires: ((emacs "27.1"))
;; Keywords: languages
;; SPDX-License-Identifier: MIT

;;; Commentary:

;; Highlighting, indentation and `--' comments for CRT scene scripts (*.crt), and the
;; crt-lsp language server for Eglot.  In init.el:
;;
;;   (add-to-list 'load-path "/path/to/crt/editors/emacs")
;;   (require 'crt-mode)
;;   (add-hook 'crt-mode-hook #'eglot-ensure)   ; diagnostics, hover, completion, ...
;;
;; `crt-lsp-program' names the server (default: crt-lsp on PATH) and
;; `crt-lsp-initialization-options' what it is started with.

;;; Code:

(defgroup crt nil
  "CRT scene scripts."
  :group 'languages
  :prefix "crt-")

(defcustom crt-indent-offset 4
  "Columns per bracket level, as crtc --format indents."
  :type 'integer
  :safe #'integerp)

(defcustom crt-lsp-program "crt-lsp"
  "The crt-lsp executable: a path, or a name found on PATH."
  :type 'string)

(defcustom crt-lsp-initialization-options nil
  "The server's initializationOptions, as a plist.
For example (:includeDirs [\"/my/includes\"] :maxSteps 1000000)."
  :type 'plist)

(defconst crt--builtins
  '("vec3" "rgb" "rgba" "sin" "cos" "tan" "asin" "acos" "atan" "atan2" "sqrt" "pow" "exp"
    "log" "abs" "floor" "ceil" "round" "min" "max" "clamp" "mix" "radians" "degrees"
    "length" "normalize" "dot" "cross" "len" "range" "str" "print" "rand" "spline")
  "The built-in functions (docs/language.md, section 10).")

(defconst crt-font-lock-keywords
  `((,(regexp-opt '("while" "for" "in" "if" "else" "include" "Settings" "Scene" "Macro" "Function"
                    "scale" "translate" "rotate")
                  'symbols)
     . font-lock-keyword-face)
    (,(regexp-opt '("true" "false") 'symbols) . font-lock-constant-face)
    ;; An attribute: a word before "->".
    ("\\_<\\([a-z][A-Za-z0-9_]*\\)\\_>[ \t]*->" 1 font-lock-variable-name-face)
    (,(regexp-opt crt--builtins 'symbols) . font-lock-builtin-face)
    (,(regexp-opt '("t" "clock") 'symbols) . font-lock-builtin-face)
    ("\\_<[A-Z][A-Za-z0-9_]*\\_>" . font-lock-type-face)
    ;; The target of an assignment.
    ("^[ \t]*\\([a-z][A-Za-z0-9_]*\\)[ \t]*=[^=]" 1 font-lock-variable-name-face)
    ("\\(?:\\_<[0-9]+\\(?:\\.[0-9]*\\)?\\|\\.[0-9]+\\)\\(?:[eE][+-]?[0-9]+\\)?"
     . 'font-lock-constant-face))
  "Highlighting for `crt-mode'.")

(defvar crt-mode-syntax-table
  (let ((table (make-syntax-table)))
    ;; "--" starts a comment that ends with the line; there are no block comments.
    (modify-syntax-entry ?- ". 12" table)
    (modify-syntax-entry ?\n ">" table)
    (modify-syntax-entry ?\" "\"" table)
    (modify-syntax-entry ?\\ "\\" table)
    (modify-syntax-entry ?_ "_" table)
    (dolist (char '(?+ ?* ?/ ?% ?^ ?! ?< ?> ?= ?? ?: ?& ?|))
      (modify-syntax-entry char "." table))
    table)
  "Syntax table for `crt-mode'.")

(defun crt--line-indentation ()
  "The indentation of the current line: one offset per open bracket around it."
  (save-excursion
    (back-to-indentation)
    (let* ((state (syntax-ppss))
           (depth (car state)))
      (cond
       ((nth 3 state) nil)                 ; inside a string that continues: leave it
       (t
        ;; A line starting with closers takes the level of the line that opened them.
        (while (and (> depth 0) (memq (char-after) '(?\) ?\] ?\})))
          (setq depth (1- depth))
          (forward-char))
        (* depth crt-indent-offset))))))

(defun crt-indent-line ()
  "Indent the current line by its bracket depth."
  (interactive)
  (let ((column (crt--line-indentation)))
    (when column
      (if (<= (current-column) (current-indentation))
          (indent-line-to column)
        (save-excursion (indent-line-to column))))))

;;;###autoload
(define-derived-mode crt-mode prog-mode "CRT"
  "Major mode for CRT scene scripts."
  :syntax-table crt-mode-syntax-table
  (setq-local comment-start "-- ")
  (setq-local comment-start-skip "--+[ \t]*")
  (setq-local comment-end "")
  (setq-local indent-line-function #'crt-indent-line)
  (setq-local indent-tabs-mode nil)
  (setq-local tab-width crt-indent-offset)
  (setq-local electric-indent-chars (append "{}[]()" electric-indent-chars))
  (setq-local font-lock-defaults '(crt-font-lock-keywords)))

;;;###autoload
(add-to-list 'auto-mode-alist '("\\.crt\\'" . crt-mode))

(defun crt-eglot-contact (&optional _interactive)
  "How Eglot starts crt-lsp: `crt-lsp-program' with `crt-lsp-initialization-options'."
  (unless (executable-find crt-lsp-program)
    (user-error "crt-lsp: `%s' is not an executable; install crt or set `crt-lsp-program'"
                crt-lsp-program))
  (if crt-lsp-initialization-options
      (list crt-lsp-program :initializationOptions crt-lsp-initialization-options)
    (list crt-lsp-program)))

;;;###autoload
(with-eval-after-load 'eglot
  (add-to-list 'eglot-server-programs '(crt-mode . crt-eglot-contact)))

(provide 'crt-mode)
;;; crt-mode.el ends here
