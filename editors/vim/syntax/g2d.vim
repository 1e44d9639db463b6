" Vim syntax file
" Language:   g2d (graph grammars that generate 2D shapes)
" Filenames:  *.g2d
" Keywords follow grammar/G2d.g4, built-in functions compiler/sema/builtins.cpp;
" editors/test/check_grammar.py checks that they stay in sync.

if exists('b:current_syntax')
  finish
endif

let s:cpo_save = &cpo
set cpo&vim

syn case match
syn iskeyword @,48-57,_

" ---- operators (defined first: arrows, comments and numbers win over them)
syn match g2dOperator "&&\|||\|[=!<>]=\|->\|[-+*%=<>!]\|/[/*]\@!"
syn match g2dSketch "@"

" ---- keywords
" declarations
syn keyword g2dDeclKeyword import param const limit priority defs axiom style space sequence compound layout
syn keyword g2dDeclKeyword node edge face enum nextgroup=g2dTypeName skipwhite skipnl
syn keyword g2dDeclKeyword fn rule nextgroup=g2dFuncName skipwhite skipnl
syn match g2dTypeName "\h\w*" contained
" `canvas LOWER to UPPER;`: neither word is reserved, so only a line that starts so
syn match g2dDeclKeyword "^\s*\zscanvas\>\ze[^;:={}]*\<to\>"
syn match g2dDeclKeyword "\(^\s*canvas\>[^;:={}]*\)\@<=\<to\>"
syn match g2dFuncName "\h\w*" contained
" rules
syn keyword g2dRuleKeyword match produce let where weight at for in insert between within split around with repeat
" `param d: int = 6 in 1..10 step 2;`: `step` is a keyword only after a range
syn match g2dRuleKeyword "\(\<in\>[^;{}]*\.\.[^;{}]*\)\@<=\<step\>"
syn keyword g2dModifier ordered parallel directed undirected merge intersect dpo
syn keyword g2dModifier pick nextgroup=g2dPickPolicy skipwhite
syn match g2dPickPolicy "\h\w*" contained nextgroup=g2dPickMeasure skipwhite
syn match g2dPickMeasure "\<\(age\|generation\)\>" contained
" booleans and logic; `not {` is a negative condition
syn keyword g2dBoolean true false
syn match g2dLogical "\<\(and\|or\|not\)\>"
syn match g2dNegative "\<not\ze\s*{"

" ---- built-in types, functions (only before `(`) and constants
syn match g2dPrimitiveType "\<\(int\|float\|bool\|string\|vec2\|vec3\)\>\(\s*(\)\@!"
syn match g2dBuiltin "\<\(sin\|cos\|tan\|asin\|acos\|atan\|atan2\|sqrt\|exp\|log\|pow\|hypot\)\ze\s*("
syn match g2dBuiltin "\<\(floor\|ceil\|round\|radians\|degrees\|abs\|sign\|clamp\|smoothstep\|min\|max\)\ze\s*("
syn match g2dBuiltin "\<\(vec2\|vec3\|dot\|cross\|length\|distance\|normalize\|perp_left\|perp_right\)\ze\s*("
syn match g2dBuiltin "\<\(rotate\|angle\|lerp\|int\|float\|str\|format\)\ze\s*("
syn match g2dBuiltin "\<\(random\|uniform\|randint\|choice\|normal\)\ze\s*("
syn keyword g2dConstant pi tau

" ---- graphs
" name: Kind, attr: type, param: type, w: * -- matched from the name on, so
" that the `:` of `c ? a : b` (a region, below) never looks like one; not the
" endpoint of a named edge `e: a -[K]-> b`
syn match g2dElement "\<\h\w*\s*:\s*\(\*\|\h\w*\>\(\s*<\=-\[\)\@!\)" contains=g2dKindRef,g2dElemType,g2dWildcard
syn match g2dKindRef "\(:\s*\)\@<=\h\w*" contained
syn match g2dElemType "\(:\s*\)\@<=\(int\|float\|bool\|string\|vec2\|vec3\)\>" contained
syn match g2dWildcard "\(:\s*\)\@<=\*" contained
" fn f(...) -> Type
syn match g2dReturnType "->\s*\h\w*\>" contains=g2dReturnArrow,g2dReturnKind,g2dReturnPrim
syn match g2dReturnArrow "->" contained
syn match g2dReturnKind "\(->\s*\)\@<=\h\w*" contained
syn match g2dReturnPrim "\(->\s*\)\@<=\(int\|float\|bool\|string\|vec2\|vec3\)\>" contained
" a -[Kind]-> b,  b <-[Kind]- a,  a -[Kind]- b
syn match g2dArrow "<\=-\[" nextgroup=g2dArrowKind skipwhite
syn match g2dArrowKind "\h\w*" contained
syn match g2dArrow "\]->\="
" style.prop = …   and   style { prop = …; }
syn match g2dStyleProp "\(\<style\s*\.\s*\)\@<=\h\w*"
syn match g2dStylePropName "\<\h\w*\ze\s*=[^=]" contained
syn region g2dStyleBlock start="\(\<style\s*\)\@<={" end="}" contains=g2dStylePropName,@g2dExpr

" c ? a : b   (so that `: b` is not read as a kind)
syn region g2dTernary matchgroup=g2dOperator start="?" end=":" end="\ze[;{}]" contains=@g2dExpr

" ---- literals
syn match g2dInteger "\<\d\+\>"
" `1..10` is a range: a `.` after digits is no fraction when a second `.` follows
syn match g2dFloat "\<\d\+\.\.\@!\d*\([eE][+-]\=\d\+\)\="
syn match g2dFloat "\(\w\|\.\)\@<!\.\d\+\([eE][+-]\=\d\+\)\="
syn match g2dFloat "\<\d\+[eE][+-]\=\d\+\>"
syn match g2dEscape "\\." contained
syn region g2dString start=+"+ skip=+\\\\\|\\"+ end=+"+ end=+$+ contains=g2dEscape

" ---- comments
syn keyword g2dTodo TODO FIXME XXX NOTE contained
syn region g2dBlockComment start="/\*" end="\*/" contains=g2dTodo,@Spell
syn match g2dLineComment "//.*$" contains=g2dTodo,@Spell

" grammars are short: always parse from the top (block comments, style blocks)
syn sync fromstart

syn cluster g2dExpr contains=g2dOperator,g2dDeclKeyword,g2dRuleKeyword,g2dModifier,g2dBoolean,g2dLogical,g2dPrimitiveType,g2dBuiltin,g2dConstant,g2dStyleProp,g2dTernary,g2dInteger,g2dFloat,g2dString,g2dBlockComment,g2dLineComment

" ---- highlighting
hi def link g2dLineComment   Comment
hi def link g2dBlockComment  Comment
hi def link g2dTodo          Todo
hi def link g2dString        String
hi def link g2dEscape        SpecialChar
hi def link g2dInteger       Number
hi def link g2dFloat         Float
hi def link g2dBoolean       Boolean
hi def link g2dDeclKeyword   Keyword
hi def link g2dRuleKeyword   Statement
hi def link g2dNegative      Statement
hi def link g2dModifier      StorageClass
hi def link g2dPickPolicy    Constant
hi def link g2dPickMeasure   Constant
hi def link g2dLogical       Operator
hi def link g2dOperator      Operator
hi def link g2dArrow         Operator
hi def link g2dPrimitiveType Type
hi def link g2dTypeName      Type
hi def link g2dKindRef       Type
hi def link g2dElemType      Type
hi def link g2dReturnArrow   Operator
hi def link g2dReturnKind    Type
hi def link g2dReturnPrim    Type
hi def link g2dArrowKind     Type
hi def link g2dFuncName      Function
hi def link g2dBuiltin       Function
hi def link g2dConstant      Constant
hi def link g2dWildcard      Special
hi def link g2dSketch        Special
hi def link g2dStyleProp     Identifier
hi def link g2dStylePropName Identifier

let b:current_syntax = 'g2d'

let &cpo = s:cpo_save
unlet s:cpo_save
