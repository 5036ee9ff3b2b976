//! The one reader of typed descriptions: a serde deserializer over a parsed JSON value that
//! remembers where it is, so an error names its field (`cells[3]`, `spec.rules.A`).
//!
//! It replaces serde_path_to_error over serde_json's value deserializer with the same results:
//! the same values, the same messages (they are serde_json's: the error type is its own) and the
//! same paths, written the same way. Those crates wrap every visitor and every seed a description
//! type uses, generically, so the wasm held each type's reading code several times over; this
//! reader drives the visitors itself, with no wrapper, and answers every typed request through one
//! `deserialize_any` once the value is of the kind asked for, as serde_json's does.

use serde::de::{self, DeserializeSeed, Visitor};
use serde_json::{Error, Map, Value};
use std::cell::RefCell;

/// Reads `T` from `value`; on failure, the error and the path of the innermost field it came
/// from ("." for the document itself, as serde_path_to_error writes it).
pub fn read<'de, T: de::Deserialize<'de>>(value: &'de Value) -> Result<T, (Error, String)> {
    let track = Track::default();
    let read = T::deserialize(Reader {
        value,
        at: &At::Root,
        track: &track,
    });
    track.placed(read)
}

/// Reads the enum `T` from an object tagged by its `tag` key (`{"kind": "remove", "cells": [3]}`),
/// as serde reads an internally tagged enum, but without buffering the object: `T` derives the
/// externally tagged form, and the tag names its variant, which reads the object's other keys.
/// The `tag` value is read at its key; the variant's content at the object's own place.
pub fn read_tagged<'de, T: de::Deserialize<'de>>(
    tag: &'static str,
    kind: Option<&'de Value>,
    rest: &'de Value,
) -> Result<T, (Error, String)> {
    let Some(kind) = kind else {
        return Err((de::Error::missing_field(tag), ".".into()));
    };
    let track = Track::default();
    let read = T::deserialize(Tagged {
        tag,
        kind,
        rest,
        track: &track,
    });
    track.placed(read)
}

/// Where a value sits in the document: a chain of steps back to the root, on the stack.
enum At<'a> {
    Root,
    Index(&'a At<'a>, usize),
    Key(&'a At<'a>, &'a str),
}

impl At<'_> {
    /// The path as serde_path_to_error writes it: keys joined by dots, indices in brackets.
    fn path(&self) -> String {
        let mut steps = Vec::new();
        let mut at = self;
        loop {
            match at {
                At::Root => break,
                At::Index(parent, i) => {
                    steps.push(format!("[{i}]"));
                    at = parent;
                }
                At::Key(parent, key) => {
                    steps.push((*key).to_string());
                    at = parent;
                }
            }
        }
        if steps.is_empty() {
            return ".".into();
        }
        let mut out = String::new();
        for (n, step) in steps.iter().rev().enumerate() {
            if n > 0 && !step.starts_with('[') {
                out.push('.');
            }
            out.push_str(step);
        }
        out
    }
}

/// The path of the first failure: the innermost, as the error travels out through every level.
#[derive(Default)]
struct Track {
    path: RefCell<Option<String>>,
}

impl Track {
    /// The outcome, its error with the path recorded ("." when none was).
    fn placed<T>(self, read: Result<T, Error>) -> Result<T, (Error, String)> {
        read.map_err(|e| (e, self.path.into_inner().unwrap_or_else(|| ".".into())))
    }

    #[cold]
    fn fail(&self, at: &At, e: Error) -> Error {
        let mut path = self.path.borrow_mut();
        if path.is_none() {
            *path = Some(at.path());
        }
        e
    }
}

#[derive(Clone, Copy)]
struct Reader<'a, 'de> {
    value: &'de Value,
    at: &'a At<'a>,
    track: &'a Track,
}

/// What serde_json's value deserializer reports a value as, when it is not what was expected.
fn unexpected(value: &Value) -> de::Unexpected<'_> {
    match value {
        Value::Null => de::Unexpected::Unit,
        Value::Bool(b) => de::Unexpected::Bool(*b),
        Value::Number(n) => match (n.as_u64(), n.as_i64()) {
            (Some(u), _) => de::Unexpected::Unsigned(u),
            (None, Some(i)) => de::Unexpected::Signed(i),
            _ => de::Unexpected::Float(n.as_f64().unwrap_or(f64::NAN)),
        },
        Value::String(s) => de::Unexpected::Str(s),
        Value::Array(_) => de::Unexpected::Seq,
        Value::Object(_) => de::Unexpected::Map,
    }
}

impl<'de> Reader<'_, 'de> {
    fn any<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, Error> {
        match self.value {
            Value::Null => visitor.visit_unit(),
            Value::Bool(b) => visitor.visit_bool(*b),
            Value::Number(n) => de::Deserializer::deserialize_any(n, visitor),
            Value::String(s) => visitor.visit_borrowed_str(s),
            Value::Array(items) => {
                let mut seq = Seq {
                    items: items.iter(),
                    index: 0,
                    at: self.at,
                    track: self.track,
                };
                let out = visitor.visit_seq(&mut seq)?;
                match seq.items.len() {
                    0 => Ok(out),
                    _ => Err(de::Error::invalid_length(
                        items.len(),
                        &"fewer elements in array",
                    )),
                }
            }
            Value::Object(map) => self.map(map, visitor),
        }
    }

    fn typed<V: Visitor<'de>>(self, fits: bool, visitor: V) -> Result<V::Value, Error> {
        match fits {
            true => de::Deserializer::deserialize_any(self, visitor),
            false => Err(self.track.fail(
                self.at,
                de::Error::invalid_type(unexpected(self.value), &visitor),
            )),
        }
    }

    fn map<V: Visitor<'de>>(
        self,
        map: &'de Map<String, Value>,
        visitor: V,
    ) -> Result<V::Value, Error> {
        let mut entries = Entries {
            entries: map.iter(),
            value: None,
            at: self.at,
            track: self.track,
        };
        let out = visitor.visit_map(&mut entries)?;
        match entries.entries.len() {
            0 => Ok(out),
            _ => Err(de::Error::invalid_length(
                map.len(),
                &"fewer elements in map",
            )),
        }
    }

    fn enumeration<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, Error> {
        let (variant, value) = match self.value {
            Value::String(variant) => (variant, None),
            Value::Object(map) if map.len() == 1 => {
                let (variant, value) = map.iter().next().expect("one entry");
                (variant, Some(value))
            }
            Value::Object(_) => {
                return Err(de::Error::invalid_value(
                    de::Unexpected::Map,
                    &"map with a single key",
                ))
            }
            other => return Err(de::Error::invalid_type(unexpected(other), &"string or map")),
        };
        visitor.visit_enum(Variant {
            name: variant,
            value,
            at: self.at,
            track: self.track,
        })
    }
}

/// The typed requests: serde_json's value deserializer answers each as `deserialize_any` does
/// when the value is of the kind asked for, and otherwise refuses it without asking the visitor
/// (so a number is not taken for an enum's variant index, say).
macro_rules! typed {
    ($($kind:ident: $($method:ident)+;)+) => {
        $($(
            fn $method<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, Error> {
                let fits = matches!(self.value, Value::$kind { .. });
                self.typed(fits, visitor)
            }
        )+)+
    };
}

impl<'de> de::Deserializer<'de> for Reader<'_, 'de> {
    type Error = Error;

    fn deserialize_any<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, Error> {
        self.any(visitor).map_err(|e| self.track.fail(self.at, e))
    }

    fn deserialize_option<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, Error> {
        match self.value {
            Value::Null => visitor.visit_none(),
            _ => visitor.visit_some(self),
        }
        .map_err(|e| self.track.fail(self.at, e))
    }

    fn deserialize_newtype_struct<V: Visitor<'de>>(
        self,
        _name: &'static str,
        visitor: V,
    ) -> Result<V::Value, Error> {
        visitor
            .visit_newtype_struct(self)
            .map_err(|e| self.track.fail(self.at, e))
    }

    fn deserialize_enum<V: Visitor<'de>>(
        self,
        _name: &'static str,
        _variants: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value, Error> {
        self.enumeration(visitor)
            .map_err(|e| self.track.fail(self.at, e))
    }

    fn deserialize_ignored_any<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, Error> {
        visitor.visit_unit()
    }

    typed! {
        Bool: deserialize_bool;
        Number: deserialize_i8 deserialize_i16 deserialize_i32 deserialize_i64 deserialize_i128
            deserialize_u8 deserialize_u16 deserialize_u32 deserialize_u64 deserialize_u128
            deserialize_f32 deserialize_f64;
        String: deserialize_char deserialize_str deserialize_string deserialize_identifier;
        Array: deserialize_seq;
        Object: deserialize_map;
        Null: deserialize_unit;
    }

    fn deserialize_bytes<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, Error> {
        let fits = matches!(self.value, Value::String(_) | Value::Array(_));
        self.typed(fits, visitor)
    }

    fn deserialize_byte_buf<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, Error> {
        self.deserialize_bytes(visitor)
    }

    fn deserialize_unit_struct<V: Visitor<'de>>(
        self,
        _name: &'static str,
        visitor: V,
    ) -> Result<V::Value, Error> {
        self.deserialize_unit(visitor)
    }

    fn deserialize_tuple<V: Visitor<'de>>(
        self,
        _len: usize,
        visitor: V,
    ) -> Result<V::Value, Error> {
        self.deserialize_seq(visitor)
    }

    fn deserialize_tuple_struct<V: Visitor<'de>>(
        self,
        _name: &'static str,
        _len: usize,
        visitor: V,
    ) -> Result<V::Value, Error> {
        self.deserialize_seq(visitor)
    }

    fn deserialize_struct<V: Visitor<'de>>(
        self,
        _name: &'static str,
        _fields: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value, Error> {
        let fits = matches!(self.value, Value::Array(_) | Value::Object(_));
        self.typed(fits, visitor)
    }
}

struct Seq<'a, 'de> {
    items: std::slice::Iter<'de, Value>,
    index: usize,
    at: &'a At<'a>,
    track: &'a Track,
}

impl<'de> de::SeqAccess<'de> for Seq<'_, 'de> {
    type Error = Error;

    fn next_element_seed<T: DeserializeSeed<'de>>(
        &mut self,
        seed: T,
    ) -> Result<Option<T::Value>, Error> {
        let Some(value) = self.items.next() else {
            return Ok(None);
        };
        let at = At::Index(self.at, self.index);
        self.index += 1;
        seed.deserialize(Reader {
            value,
            at: &at,
            track: self.track,
        })
        .map(Some)
        .map_err(|e| self.track.fail(&at, e))
    }

    fn size_hint(&self) -> Option<usize> {
        Some(self.items.len())
    }
}

struct Entries<'a, 'de> {
    entries: serde_json::map::Iter<'de>,
    value: Option<(&'de str, &'de Value)>,
    at: &'a At<'a>,
    track: &'a Track,
}

impl<'de> de::MapAccess<'de> for Entries<'_, 'de> {
    type Error = Error;

    fn next_key_seed<K: DeserializeSeed<'de>>(
        &mut self,
        seed: K,
    ) -> Result<Option<K::Value>, Error> {
        let Some((key, value)) = self.entries.next() else {
            return Ok(None);
        };
        self.value = Some((key, value));
        seed.deserialize(de::value::BorrowedStrDeserializer::new(key))
            .map(Some)
            .map_err(|e| self.track.fail(&At::Key(self.at, key), e))
    }

    fn next_value_seed<V: DeserializeSeed<'de>>(&mut self, seed: V) -> Result<V::Value, Error> {
        let (key, value) = self
            .value
            .take()
            .ok_or_else(|| de::Error::custom("value is missing"))?;
        let at = At::Key(self.at, key);
        seed.deserialize(Reader {
            value,
            at: &at,
            track: self.track,
        })
        .map_err(|e| self.track.fail(&at, e))
    }

    fn size_hint(&self) -> Option<usize> {
        Some(self.entries.len())
    }
}

/// An enum's variant: its name, and its content when it is written as `{"Name": content}`.
struct Variant<'a, 'de> {
    name: &'de str,
    value: Option<&'de Value>,
    at: &'a At<'a>,
    track: &'a Track,
}

impl<'a, 'de> de::EnumAccess<'de> for Variant<'a, 'de> {
    type Error = Error;
    type Variant = Self;

    fn variant_seed<S: DeserializeSeed<'de>>(self, seed: S) -> Result<(S::Value, Self), Error> {
        Ok((
            seed.deserialize(de::value::BorrowedStrDeserializer::new(self.name))?,
            self,
        ))
    }
}

impl<'de> de::VariantAccess<'de> for Variant<'_, 'de> {
    type Error = Error;

    fn unit_variant(self) -> Result<(), Error> {
        self.content(|inner| match inner {
            Some(inner) => de::Deserialize::deserialize(inner),
            None => Ok(()),
        })
    }

    fn newtype_variant_seed<T: DeserializeSeed<'de>>(self, seed: T) -> Result<T::Value, Error> {
        self.content(|inner| seed.deserialize(shaped(inner, |_| true, "newtype variant")?))
    }

    fn tuple_variant<V: Visitor<'de>>(self, _len: usize, visitor: V) -> Result<V::Value, Error> {
        self.content(|inner| {
            let inner = shaped(inner, Value::is_array, "tuple variant")?;
            match inner.value {
                Value::Array(items) if items.is_empty() => visitor.visit_unit(),
                _ => inner.any(visitor),
            }
        })
    }

    fn struct_variant<V: Visitor<'de>>(
        self,
        _fields: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value, Error> {
        self.content(|inner| shaped(inner, Value::is_object, "struct variant")?.any(visitor))
    }
}

/// A variant's content when it is there and `fits`; else serde_json's error for `what`.
fn shaped<'r, 'de>(
    inner: Option<Reader<'r, 'de>>,
    fits: fn(&Value) -> bool,
    what: &'static str,
) -> Result<Reader<'r, 'de>, Error> {
    match inner {
        Some(inner) if fits(inner.value) => Ok(inner),
        Some(inner) => Err(de::Error::invalid_type(unexpected(inner.value), &what)),
        None => Err(de::Error::invalid_type(de::Unexpected::UnitVariant, &what)),
    }
}

impl<'de> Variant<'_, 'de> {
    /// Reads the variant's content, which sits at the variant's name: every failure is placed
    /// there, the content's own or a missing one.
    fn content<T>(
        self,
        read: impl FnOnce(Option<Reader<'_, 'de>>) -> Result<T, Error>,
    ) -> Result<T, Error> {
        let at = At::Key(self.at, self.name);
        let inner = self.value.map(|value| Reader {
            value,
            at: &at,
            track: self.track,
        });
        read(inner).map_err(|e| self.track.fail(&at, e))
    }
}

/// An object tagged by one of its keys, read as an enum: see [`read_tagged`].
struct Tagged<'a, 'de> {
    tag: &'static str,
    kind: &'de Value,
    rest: &'de Value,
    track: &'a Track,
}

impl<'de> de::Deserializer<'de> for Tagged<'_, 'de> {
    type Error = Error;

    fn deserialize_any<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, Error> {
        visitor.visit_enum(self)
    }

    serde::forward_to_deserialize_any! {
        bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string bytes byte_buf option
        unit unit_struct newtype_struct seq tuple tuple_struct map struct enum identifier
        ignored_any
    }
}

impl<'a, 'de> de::EnumAccess<'de> for Tagged<'a, 'de> {
    type Error = Error;
    type Variant = Reader<'a, 'de>;

    fn variant_seed<S: DeserializeSeed<'de>>(
        self,
        seed: S,
    ) -> Result<(S::Value, Self::Variant), Error> {
        let at = At::Key(&At::Root, self.tag);
        let name = seed.deserialize(Reader {
            value: self.kind,
            at: &at,
            track: self.track,
        })?;
        let content = Reader {
            value: self.rest,
            at: &At::Root,
            track: self.track,
        };
        Ok((name, content))
    }
}

/// The content of a tagged object's variant: the object's other keys.
impl<'de> de::VariantAccess<'de> for Reader<'_, 'de> {
    type Error = Error;

    fn unit_variant(self) -> Result<(), Error> {
        Ok(())
    }

    fn newtype_variant_seed<T: DeserializeSeed<'de>>(self, seed: T) -> Result<T::Value, Error> {
        seed.deserialize(self)
    }

    fn tuple_variant<V: Visitor<'de>>(self, _len: usize, visitor: V) -> Result<V::Value, Error> {
        de::Deserializer::deserialize_seq(self, visitor)
    }

    fn struct_variant<V: Visitor<'de>>(
        self,
        fields: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value, Error> {
        de::Deserializer::deserialize_struct(self, "", fields, visitor)
    }
}

#[cfg(test)]
mod tests;
