// The .g2d language: graph grammars that generate 2D shapes.
// The parse tree never leaves compiler/parse: it is converted to our own AST.
grammar G2d;

program     : topDecl* EOF ;

topDecl
    : spaceDecl
    | importDecl
    | paramDecl
    | constDecl
    | enumDecl
    | kindDecl
    | fnDecl
    | axiomDecl
    | limitDecl
    | priorityDecl
    | defsDecl
    | mergeDecl
    | sequenceDecl
    | compoundDecl
    | layoutDecl
    | canvasDecl
    | ruleDecl
    ;

// `space 3d;`: positions are vec3 (the default is `space 2d;`).
spaceDecl   : 'space' SPACE_DIM ';' ;
importDecl  : 'import' STRING ';' ;
// param depth: int = 6 in 1..10;   param tilt: float = 0.5 in 0..1 step 0.05;
// The range (int and float only) bounds the values a run accepts; `step` is
// not a keyword (it may still name anything): sema checks the word.
paramDecl   : 'param' name=(ID | 'merge') ':' typeRef '=' expr paramRange? ';' ;
paramRange  : 'in' lower=expr '..' upper=expr (stepWord=ID step=expr)? ;
constDecl   : 'const' ID (':' typeRef)? '=' expr ';' ;
enumDecl    : 'enum' ID '{' ID (',' ID)* ','? '}' ;
fnDecl      : 'fn' ID '(' (fnParam (',' fnParam)*)? ')' '->' typeRef '=' expr ';' ;
fnParam     : ID ':' typeRef ;
limitDecl   : 'limit' expr ';' ;
priorityDecl: 'priority' signedInt priorityOption+ ';' ;
priorityOption
    : 'limit' expr      # priorityLimit
    | 'parallel'        # priorityParallel
    | ID                # priorityWord      // `generation` (not a keyword: it may name attributes)
    ;
defsDecl    : 'defs' STRING ';' ;
// merge within TOLERANCE;   every rule merges coinciding nodes (G^3 §3.1).
// `merge` is a keyword that may also name a parameter (`param merge: bool`).
mergeDecl   : 'merge' 'within' expr ';' ;
// sequence { A; B; A; }   a G^3 command list: each once, in order, in parallel;
// sequence L { A; B; }     a named list (G^3's rule, §2.4.6) that lists name
sequenceDecl: 'sequence' name=ID? sequenceBody ;
sequenceBody: '{' sequenceItem* '}' ;
sequenceItem
    : ID ';'                        # sequenceName     // a rule, compound or named list
    | 'repeat' expr sequenceBody    # sequenceRepeat   // the entries, N times (N may read parameters)
    ;
// compound C { match { f: Face …; } sequence { A; B; } }   G^3's compound
// command (§3.3): its commands, in order, within the scope of each match;
// its lets are values of each match that its commands' rules read as C.name
compoundDecl: 'compound' ID '{' matchBlock letStmt* 'sequence' sequenceBody '}' ;

// layout angles { canvas_min = (0, 0); canvas_max = (40, 30); }   new nodes
// are placed by Merrell 2023's drawing step (edges keep their kinds' angles)
layoutDecl  : 'layout' ID '{' styleProp* '}' ;

// canvas (x0, y0) to (x1, y1);   the SVG's viewBox, exactly, in grammar units
// (y up). `canvas` and `to` are not keywords (they may still name anything):
// the predicate lets only the word `canvas` start this declaration, so that a
// misspelt keyword is still reported as one; sema checks the `to`.
canvasDecl  : {getCurrentToken()->getText() == "canvas"}? ID lower=expr to=ID upper=expr ';' ;

typeRef     : ID ;

// ---- kinds -----------------------------------------------------------------
kindDecl
    : 'node' ID kindBody                                  # nodeKind
    | 'edge' ID (DIRECTED='directed' | UNDIRECTED='undirected')? kindBody  # edgeKind
    | 'face' ID option=ID? kindBody                       # faceKind      // option: `oriented` (not a keyword)
    ;
kindBody    : '{' kindMember* '}' | ';' ;
kindMember
    : ID ':' typeRef ('=' expr)? ';'                      # attrDecl
    | 'style' '{' styleProp* '}'                          # styleBlock
    | 'layout' '{' styleProp* '}'                         # layoutBlock
    ;
styleProp   : ID '=' expr ';' ;

// ---- graphs ----------------------------------------------------------------
axiomDecl   : 'axiom' '{' graphStmt* '}' ;

graphStmt
    : nodeStmt
    | edgeStmt
    | faceStmt
    ;

// name: Kind [@ sketch] [at position] [{ assignments }] [where condition] ;
// name [@ sketch] [at position] [{ assignments }] ;   (a kept element in a daughter)
nodeStmt
    : ID (':' (kind=ID | wild='*'))? sketch? position? assignments? whereClause? ';'
    ;
sketch      : '@' '(' signedNumber ',' signedNumber ')' ;
position    : 'at' expr ;
assignments : '{' (assignment (',' assignment)* ','?)? '}' ;
assignment  : (isStyle='style' '.')? ID '=' expr ;
whereClause : 'where' expr ;

// [name:] a -[Kind {..}]-> b   directed,   a -[Kind]- b   undirected
edgeStmt
    : (name=ID ':')? src=nodeRef edgeArrow dst=nodeRef whereClause? ';'
    ;
// A node: its name, or in a `for` loop `prev.NAME` / `next.NAME`, the node
// NAME of the neighbouring turn.
nodeRef     : ID ('.' member=ID)? ;
edgeArrow
    : '-[' edgeLabel ']->'     # directedArrow
    | '<-[' edgeLabel ']-'     # reversedArrow
    | '-[' edgeLabel ']-'      # undirectedArrow
    ;
edgeLabel   : ID assignments? ;

// [name:] Kind(corner, corner, corner, ...) [{ assignments }] [where condition] ;
// Kind(all t) / Kind(all t reversed): node t of every turn of a `for` loop
faceStmt
    : (name=ID ':')? kind=ID '(' (ring=ringCorners | corners+=nodeRef (',' corners+=nodeRef)*) ')' assignments? whereClause? ';'
    ;
// `all` and `reversed` are plain names (they may still name anything): sema checks them
ringCorners : every=ID node=ID order=ID? ;

// ---- rules -----------------------------------------------------------------
ruleDecl    : 'rule' ID ruleOption* '{' matchBlock ruleItem* '}' ;
ruleOption
    : 'priority' signedInt          # rulePriority
    | 'pick' how=ID measure=ID?      # rulePick       // `pick oldest generation`
    | 'ordered'                     # ruleOrdered
    | 'parallel'                    # ruleParallel
    | word=('merge' | 'intersect' | 'dpo')  # ruleWordOption
    | 'weight' expr                 # ruleWeight     // chosen among a priority's matching rules by weight
    | 'limit' expr                  # ruleLimit      // at most N steps apply the rule
    ;
matchBlock  : 'match' '{' matchStmt* '}' ;
matchStmt
    : graphStmt                     # matchGraph
    | 'where' expr ';'              # matchWhere
    | 'not' '{' matchStmt* '}'      # matchNac
    ;
ruleItem
    : letStmt
    | produceBlock
    ;
letStmt     : 'let' ID (':' typeRef)? '=' expr ';' ;
produceBlock: 'produce' ('weight' expr)? '{' produceStmt* '}' ;
produceStmt
    : letStmt
    | graphStmt
    | forStmt
    | insertStmt
    | splitStmt
    ;
// insert m between a and b;   (m joins every face with side a–b, between them)
insertStmt  : 'insert' node=ID 'between' first=ID 'and' second=ID ';' ;
// split f [around Kind at POS {…}] with EdgeKind {…} [for c in f.corners where COND];
// (G^3's Split face: the chosen corners cut f, around a new node or, two, by a chord)
splitStmt
    : 'split' face=ID ('around' centreKind=ID position centre=assignments?)? 'with' edgeKind=ID edge=assignments?
      ('for' var=ID 'in' loopFace=ID '.' what=ID 'where' expr)? ';'
    ;
// for (u, v) in f.sides { … }   or   for c in f.corners { … }
forStmt
    : 'for' (var=ID | '(' first=ID ',' second=ID ')') 'in' face=ID '.' what=ID '{' produceStmt* '}'
    ;

// ---- expressions (lowest precedence last) ----------------------------------
expr
    : primary                                               # primaryExpr
    | expr '.' ID                                           # memberExpr
    | op=('-' | '+' | '!') expr                             # unaryExpr
    | expr op=('*' | '/' | '%') expr                        # mulExpr
    | expr op=('+' | '-') expr                              # addExpr
    | expr op=('<' | '<=' | '>' | '>=') expr                # relExpr
    | expr op=('==' | '!=') expr                            # eqExpr
    | op='not' expr                                         # notExpr
    | expr op=('and' | '&&') expr                           # andExpr
    | expr op=('or' | '||') expr                            # orExpr
    | <assoc=right> expr '?' expr ':' expr                  # condExpr
    ;

primary
    : INT                                                   # intLit
    | FLOAT                                                 # floatLit
    | STRING                                                # stringLit
    | ('true' | 'false')                                    # boolLit
    | ID '(' (expr (',' expr)*)? ')'                        # callExpr
    | name=(ID | 'merge')                                   # nameExpr
    | '(' expr ',' expr (',' expr)? ')'                     # vecLit
    | '(' expr ')'                                          # parenExpr
    ;

signedInt   : '-'? INT ;
signedNumber: '-'? (INT | FLOAT) ;

// ---- lexer -----------------------------------------------------------------
SPACE_DIM   : [23] [d] ;
ID          : [a-zA-Z_] [a-zA-Z_0-9]* ;
// `1..10` is a range, not the float `1.` and the float `.10`: the parser's
// lexer (compiler/parse/range_lexer.cpp) reads `1.` before a `.` as the int 1.
FLOAT       : DIGITS '.' DIGITS? EXPONENT? | '.' DIGITS EXPONENT? | DIGITS EXPONENT ;
INT         : DIGITS ;
fragment DIGITS   : [0-9]+ ;
fragment EXPONENT : [eE] [+-]? DIGITS ;
STRING      : '"' ( ~["\\\r\n] | '\\' . )* '"' ;
LINE_COMMENT  : '//' ~[\r\n]* -> skip ;
BLOCK_COMMENT : '/*' .*? '*/' -> skip ;
WS          : [ \t\r\n\f]+ -> skip ;
// Unterminated constructs and stray characters become tokens so that the
// parser, not the lexer, reports them in words.
UNTERMINATED_STRING  : '"' ( ~["\\\r\n] | '\\' . )* ;
UNTERMINATED_COMMENT : '/*' ( ~'*' | '*'+ ~[*/] )* '*'* EOF ;   // contains no `*/`
ERRCHAR     : . ;
