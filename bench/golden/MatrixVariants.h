#pragma once
// The forms of a technique the matrix renders (GoldenMatrix), and the one key each form's files go by.
// A technique's default form is named by its name ("raytraced"); each variant it declares
// (TechniqueInfo::matrixVariants, techniques/MatrixVariant.h) by its spec, name and properties
// ("raytraced:mode=soft"): that is the technique field of its cells (MatrixCell::technique), which
// `bench golden --technique` takes and `-t` would run. Its goldens, bounds and row of
// results/goldens/MATRIX.md are keyed by key(): the name itself for a default form (the files every
// technique had before variants existed), the spec with ':' as '.' for a variant
// ("raytraced.mode=soft": results/goldens/<scene>/raytraced.mode=soft.visibility.png, bounds.json's
// "raytraced.mode=soft/<scene>/light0"), every character but letters, digits and ". = - _ ," written
// as '_', so that a key is a file name on any system and a cell of a Markdown table.
#include <optional>
#include <string>
#include <vector>

#include "techniques/MatrixVariant.h"

namespace sb {

class MatrixVariants {
public:
    /// The forms of registered technique `name`: `name`, then its variants' specs in declaration order.
    static std::vector<std::string> of(const std::string& name);
    /// The forms of every registered technique, in registry order (each technique before its variants).
    static std::vector<std::string> all();
    /// What `bench golden --technique` asks for, in the order asked and once each: a technique's name
    /// is its default form and its variants (the technique's cells), a variant's spec that variant alone,
    /// `auto` itself. An unknown name is the registry's error; a spec that is not one of the technique's
    /// variants is sb::Error(BadInput) naming the forms it has.
    static std::vector<std::string> select(const std::vector<std::string>& requested);
    /// The variant a cell's technique field names, or nullopt for a default form (a bare name, `auto`).
    static std::optional<MatrixVariant> variantOf(const std::string& technique);
    /// The registry name of a cell's technique field ("raytraced" of "raytraced:mode=soft").
    static std::string nameOf(const std::string& technique);
    /// The key of a cell's goldens, bounds and row (above).
    static std::string key(const std::string& technique);
};

} // namespace sb
