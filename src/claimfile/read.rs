//! Reading a claims file: the serde types of its shape (`deny_unknown_fields` everywhere), the
//! two formats (TOML with the `toml` crate, JSON with `serde_json`), and the positions of its
//! keys, so that every error is one line `FILE:LINE: WHERE: key KEY: WHAT`.
//!
//! Errors found while deserializing carry their position (`toml::de::Error::span`,
//! `serde_json::Error::line`) and their path (`serde_path_to_error`). Errors found later (a bad
//! formula, an unknown kind) are located through an index of the file's keys: path
//! (`claim.2.lhs`) to byte offset, built from `toml`'s spanned document tree
//! (`toml::de::DeTable`) or, for JSON, by a small scanner of the (already validated) text, which
//! also refuses a key given twice in one object (`serde_json` would keep the last silently).

use serde::Deserialize;
use serde_json::{Map, Value};
use std::collections::{HashMap, HashSet};

/// The top level of a claims file.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawFile {
    /// `[paper]`.
    pub paper: Option<RawPaper>,
    /// `[define]`: name -> formula (string or number) or vector (array).
    pub define: Option<Map<String, Value>>,
    /// `[latex]`: the file's notation, name -> LaTeX.
    pub latex: Option<Map<String, Value>>,
    /// The variables of every claim (optional): any other free name is warned about.
    pub variables: Option<Vec<String>>,
    /// `[[claim]]`.
    #[serde(default)]
    pub claim: Vec<RawClaim>,
}

/// `[paper]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawPaper {
    /// The source name (what the report filters by).
    pub name: Option<String>,
    /// The title.
    pub title: Option<String>,
    /// The bibliographic reference.
    pub reference: Option<String>,
}

/// A string or a list of strings.
#[derive(Debug, Deserialize)]
#[serde(untagged)]
pub enum OneOrMany {
    /// One.
    One(String),
    /// Several.
    Many(Vec<String>),
}

impl OneOrMany {
    /// As a list.
    pub fn list(&self) -> Vec<String> {
        match self {
            OneOrMany::One(s) => vec![s.clone()],
            OneOrMany::Many(v) => v.clone(),
        }
    }
}

/// One `[[claim]]`: the keys of every kind (which keys a kind takes is checked after reading,
/// with an error naming the key).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawClaim {
    pub id: String,
    pub kind: String,
    pub statement: Option<String>,
    pub expect: Option<String>,
    pub latex: Option<Map<String, Value>>,
    pub name: Option<OneOrMany>,
    pub lhs: Option<String>,
    pub rhs: Option<String>,
    #[serde(rename = "where")]
    pub where_: Option<Vec<String>>,
    pub domains: Option<Vec<String>>,
    pub field: Option<String>,
    pub corrected: Option<String>,
    pub expr: Option<String>,
    pub printed: Option<OneOrMany>,
    pub random: Option<u64>,
    pub seed: Option<u64>,
    pub at: Option<Vec<Map<String, Value>>>,
    pub problem: Option<Value>,
    pub expect_fields: Option<Map<String, Value>>,
    /// The claim's variables (with the file's): any other free name is warned about.
    pub variables: Option<Vec<String>>,
}

/// The keys of [`RawClaim`] that are set (for "key X does not belong to kind Y").
pub fn present_keys(c: &RawClaim) -> Vec<&'static str> {
    let mut k = Vec::new();
    let mut add = |name: &'static str, set: bool| {
        if set {
            k.push(name)
        }
    };
    add("name", c.name.is_some());
    add("lhs", c.lhs.is_some());
    add("rhs", c.rhs.is_some());
    add("where", c.where_.is_some());
    add("domains", c.domains.is_some());
    add("field", c.field.is_some());
    add("corrected", c.corrected.is_some());
    add("expr", c.expr.is_some());
    add("printed", c.printed.is_some());
    add("random", c.random.is_some());
    add("seed", c.seed.is_some());
    add("at", c.at.is_some());
    add("problem", c.problem.is_some());
    add("expect_fields", c.expect_fields.is_some());
    k
}

/// The format of a file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// TOML.
    Toml,
    /// JSON.
    Json,
}

/// The format: by extension, else by content (JSON starts with `{`).
pub fn format_of(path: &str, text: &str) -> Format {
    let lower = path.to_ascii_lowercase();
    if lower.ends_with(".toml") {
        Format::Toml
    } else if lower.ends_with(".json") || text.trim_start().starts_with('{') {
        Format::Json
    } else {
        Format::Toml
    }
}

/// Where the keys of a file are: path (`claim.2.lhs`, `define.A`) to byte offset.
pub struct Index {
    /// The byte offset of every newline of the text, in order.
    newlines: Vec<usize>,
    at: HashMap<String, usize>,
}

impl Index {
    fn new(text: &str, at: HashMap<String, usize>) -> Index {
        let newlines = text
            .bytes()
            .enumerate()
            .filter(|&(_, b)| b == b'\n')
            .map(|(i, _)| i)
            .collect();
        Index { newlines, at }
    }

    /// The line (from 1) of a byte offset: a binary search in the newlines, so that looking up
    /// every key of a large file stays linear in its size.
    pub fn line_of(&self, offset: usize) -> usize {
        1 + self.newlines.partition_point(|&n| n < offset)
    }

    /// The line of a path, or of its nearest ancestor that is in the index (1 if none).
    pub fn line(&self, path: &str) -> usize {
        let mut p = path;
        loop {
            if let Some(&o) = self.at.get(p) {
                return self.line_of(o);
            }
            match p.rfind('.') {
                Some(i) => p = &p[..i],
                None => return 1,
            }
        }
    }
}

/// A reading error: the line and the message (without the file name).
pub struct ReadError {
    /// The line (from 1).
    pub line: usize,
    /// `WHERE: key KEY: WHAT` or just `WHAT`.
    pub message: String,
}

/// Reads the text into the raw shape and its key index.
///
/// # Errors
/// A syntax error or anything the types refuse, with its line and path.
pub fn read(text: &str, format: Format) -> Result<(RawFile, Index), ReadError> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    match format {
        Format::Toml => read_toml(text),
        Format::Json => read_json(text),
    }
}

fn one_line(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// `claim "ID": key KEY` (or `define: key A`, `paper: key title`) for a serde path.
fn describe(path: &serde_path_to_error::Path, ids: &[Option<String>]) -> String {
    use serde_path_to_error::Segment;
    let segs: Vec<String> = path
        .iter()
        .filter_map(|s| match s {
            Segment::Seq { index } => Some(index.to_string()),
            Segment::Map { key } | Segment::Enum { variant: key } => Some(key.clone()),
            Segment::Unknown => None,
        })
        .collect();
    where_key(&segs, ids)
}

/// The context of a path given as segments.
pub fn where_key(segs: &[String], ids: &[Option<String>]) -> String {
    match segs {
        [] => String::new(),
        [c, i, rest @ ..] if c == "claim" => {
            let who = match i
                .parse::<usize>()
                .ok()
                .and_then(|i| ids.get(i).cloned().flatten())
            {
                Some(id) => format!("claim {id:?}"),
                None => format!(
                    "claim #{}",
                    i.parse::<usize>()
                        .map_or(i.clone(), |i| (i + 1).to_string())
                ),
            };
            if rest.is_empty() {
                who
            } else {
                format!("{who}: key {}", rest.join("."))
            }
        }
        [table] => format!("key {table}"),
        [table, rest @ ..] => format!("{table}: key {}", rest.join(".")),
    }
}

/// The ids of the claims as far as a loose reading finds them (for messages).
fn loose_ids(v: Option<Value>) -> Vec<Option<String>> {
    v.and_then(|v| v.get("claim").and_then(Value::as_array).cloned())
        .map(|a| {
            a.iter()
                .map(|c| c.get("id").and_then(Value::as_str).map(str::to_string))
                .collect()
        })
        .unwrap_or_default()
}

fn with_context(context: &str, message: &str) -> String {
    // serde names a duplicate or missing field only in its message: name it as the key.
    let field = ["duplicate field `", "missing field `"]
        .iter()
        .find_map(|p| message.strip_prefix(p))
        .and_then(|rest| rest.split('`').next());
    if let (Some(f), false) = (field, context.contains("key ")) {
        let context = if context.is_empty() {
            format!("key {f}")
        } else {
            format!("{context}: key {f}")
        };
        return format!("{context}: {message}");
    }
    if context.is_empty() {
        message.to_string()
    } else {
        format!("{context}: {message}")
    }
}

/// The document's nesting depth within the `depth` limit (`crate::solve::depth`), checked
/// before the recursive parsers see it.
fn check_depth(
    text: &str,
    check: fn(&str) -> Result<(), (usize, exactcheck_core::limits::LimitError)>,
) -> Result<(), ReadError> {
    check(text).map_err(|(at, e)| ReadError {
        line: line_in(text, at),
        message: e.to_string(),
    })
}

fn read_toml(text: &str) -> Result<(RawFile, Index), ReadError> {
    check_depth(text, crate::solve::depth::check_toml)?;
    let syntax = |e: toml::de::Error| {
        let line = e.span().map_or(1, |s| line_in(text, s.start));
        ReadError {
            line,
            message: format!("TOML: {}", one_line(e.message())),
        }
    };
    let tree = toml::de::DeTable::parse(text).map_err(syntax)?;
    let mut at = HashMap::new();
    index_toml_table(tree.get_ref(), "", &mut at);
    let index = Index::new(text, at);
    let de = toml::Deserializer::parse(text).map_err(syntax)?;
    let raw: RawFile = serde_path_to_error::deserialize(de).map_err(|e| {
        let ids = loose_ids(toml::from_str::<Value>(text).ok());
        let context = describe(e.path(), &ids);
        let path = e.path().to_string();
        let inner = e.into_inner();
        let line = match inner.span() {
            Some(s) => line_in(text, s.start),
            None => index.line(&dotted(&path)),
        };
        ReadError {
            line,
            message: with_context(&context, &one_line(inner.message())),
        }
    })?;
    Ok((raw, index))
}

/// `claim[2].lhs` -> `claim.2.lhs`.
fn dotted(path: &str) -> String {
    path.replace('[', ".").replace(']', "")
}

fn line_in(text: &str, offset: usize) -> usize {
    1 + text.as_bytes()[..offset.min(text.len())]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
}

fn join(prefix: &str, key: &str) -> String {
    if prefix.is_empty() {
        key.to_string()
    } else {
        format!("{prefix}.{key}")
    }
}

fn index_toml_table(t: &toml::de::DeTable<'_>, prefix: &str, at: &mut HashMap<String, usize>) {
    for (k, v) in t {
        let path = join(prefix, k.get_ref());
        at.insert(path.clone(), k.span().start);
        index_toml_value(v, &path, at);
    }
}

fn index_toml_value(
    v: &toml::Spanned<toml::de::DeValue<'_>>,
    path: &str,
    at: &mut HashMap<String, usize>,
) {
    match v.get_ref() {
        toml::de::DeValue::Table(t) => index_toml_table(t, path, at),
        toml::de::DeValue::Array(a) => {
            for (i, x) in a.iter().enumerate() {
                let p = join(path, &i.to_string());
                at.insert(p.clone(), x.span().start);
                index_toml_value(x, &p, at);
            }
        }
        _ => {}
    }
}

fn read_json(text: &str) -> Result<(RawFile, Index), ReadError> {
    check_depth(text, crate::solve::depth::check_json)?;
    let mut de = serde_json::Deserializer::from_str(text);
    // The depth was bounded by `check_depth` above.
    de.disable_recursion_limit();
    let raw: Result<RawFile, _> = serde_path_to_error::deserialize(&mut de);
    let raw = match raw {
        Ok(r) => {
            de.end().map_err(|e| ReadError {
                line: e.line().max(1),
                message: "JSON: trailing characters after the top-level object".into(),
            })?;
            r
        }
        Err(e) => {
            let ids = loose_ids(serde_json::from_str(text).ok());
            let context = describe(e.path(), &ids);
            let inner = e.into_inner();
            let message = inner.to_string();
            let message = match message.rfind(" at line ") {
                Some(i) => message[..i].to_string(),
                None => message,
            };
            let message = if inner.is_syntax() || inner.is_eof() {
                format!("JSON: {message}")
            } else {
                message
            };
            return Err(ReadError {
                line: inner.line().max(1),
                message: with_context(&context, &message),
            });
        }
    };
    let mut scanner = JsonScanner {
        s: text.as_bytes(),
        i: 0,
        at: HashMap::new(),
    };
    scanner.value("")?;
    Ok((raw, Index::new(text, scanner.at)))
}

/// Positions of the keys of JSON text that `serde_json` has already accepted.
struct JsonScanner<'a> {
    s: &'a [u8],
    i: usize,
    at: HashMap<String, usize>,
}

impl JsonScanner<'_> {
    fn ws(&mut self) {
        while self.i < self.s.len() && self.s[self.i].is_ascii_whitespace() {
            self.i += 1;
        }
    }

    /// A string starting at `"`; returns its raw content (escapes kept, enough for keys).
    fn string(&mut self) -> String {
        let start = self.i + 1;
        self.i += 1;
        while self.i < self.s.len() && self.s[self.i] != b'"' {
            if self.s[self.i] == b'\\' {
                self.i += 1;
            }
            self.i += 1;
        }
        let raw = String::from_utf8_lossy(&self.s[start..self.i.min(self.s.len())]).into_owned();
        self.i += 1;
        raw
    }

    fn value(&mut self, path: &str) -> Result<(), ReadError> {
        self.ws();
        match self.s.get(self.i) {
            Some(b'{') => {
                self.i += 1;
                let mut seen: HashSet<String> = HashSet::new();
                loop {
                    self.ws();
                    match self.s.get(self.i) {
                        Some(b'}') | None => {
                            self.i += 1;
                            return Ok(());
                        }
                        Some(b',') => self.i += 1,
                        Some(b'"') => {
                            let pos = self.i;
                            let key = self.string();
                            let p = join(path, &key);
                            if seen.contains(&key) {
                                let segs: Vec<String> = p.split('.').map(str::to_string).collect();
                                return Err(ReadError {
                                    line: line_in(&String::from_utf8_lossy(self.s), pos),
                                    message: format!(
                                        "{}: the key is given twice",
                                        where_key(&segs, &[])
                                    ),
                                });
                            }
                            seen.insert(key);
                            self.at.insert(p.clone(), pos);
                            self.ws();
                            self.i += 1; // ':'
                            self.value(&p)?;
                        }
                        Some(_) => self.i += 1,
                    }
                }
            }
            Some(b'[') => {
                self.i += 1;
                let mut k = 0;
                loop {
                    self.ws();
                    match self.s.get(self.i) {
                        Some(b']') | None => {
                            self.i += 1;
                            return Ok(());
                        }
                        Some(b',') => self.i += 1,
                        Some(_) => {
                            let p = join(path, &k.to_string());
                            self.at.insert(p.clone(), self.i);
                            self.value(&p)?;
                            k += 1;
                        }
                    }
                }
            }
            Some(b'"') => {
                self.string();
                Ok(())
            }
            _ => {
                while self.i < self.s.len() && !matches!(self.s[self.i], b',' | b'}' | b']') {
                    self.i += 1;
                }
                Ok(())
            }
        }
    }
}
