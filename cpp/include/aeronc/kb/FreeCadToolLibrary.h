#pragma once
// FreeCAD tool bits (.fctb) and tool libraries (.fctl): reading, writing and the mapping to
// the selector's tools. No FreeCAD here, only its file formats: a .fctb is JSON with a shape
// file name and quantity strings ("5.0000 mm"); a .fctl lists tool numbers and bit files.
//
// Documents are kept as text so that a library imported and exported again is the same
// bytes; a document is rewritten only where a tool dimension was changed.
#include <aeronc/toolselect/Tool.h>

#include <optional>
#include <string>
#include <vector>

namespace aeronc::kb {

struct FreeCadBit {
    int nr = 0;            // the tool number in the library
    std::string fileName;  // e.g. "5mm_Endmill.fctb"
    std::string document;  // the .fctb JSON text
};

struct FreeCadLibrary {
    std::string name;      // the .fctl file name without extension
    int version = 1;
    std::string document;  // the .fctl JSON text as read; empty: write a new one
    std::vector<FreeCadBit> bits;
};

// Reads an .fctl and every .fctb it lists. A relative bit path is looked up beside the
// library, then in ../Bit (FreeCAD's layout). Throws aeronc::inputError naming the file and
// what is wrong with it.
FreeCadLibrary readFreeCadLibrary(const std::string& fctlPath);

// Writes <folder>/Library/<name>.fctl and <folder>/Bit/<bit file> for every bit, each under a
// temporary name first. Returns the paths written, the library first.
std::vector<std::string> writeFreeCadLibrary(const FreeCadLibrary& library, const std::string& folder);

// What a bit document does not say.
struct BitDefaults {
    std::string toolMaterial = "carbide";  // when the bit has no "Material" attribute
    int flutes = 2;                         // when the bit has no "Flutes" attribute
};

struct BitTool {
    toolselect::Tool tool;
    std::optional<double> overallLength;  // the bit's Length
};

// The tool a bit describes: its id is the bit's file name without extension; endmill, bullnose,
// ballend and drill shapes map to flat, bull, ball and drill, every other shape to "other".
// Throws aeronc::inputError naming the bit for a missing diameter or an unreadable quantity.
BitTool toolFromBit(const FreeCadBit& bit, const BitDefaults& defaults);

// The bit document with the tool's dimensions written into its parameters; the text is
// returned unchanged when every dimension already matches.
std::string bitWithTool(const std::string& document, const toolselect::Tool& tool,
                        std::optional<double> overallLength);

// A new bit document for a tool that never came from FreeCAD.
std::string newBitFor(const toolselect::Tool& tool, std::optional<double> overallLength);

// A bit file name for a tool id: characters FreeCAD's file dialogs dislike become '_'.
std::string bitFileNameFor(const std::string& toolId);

// A quantity string in mm: "5.0000 mm" -> 5, "0.25 in" -> 6.35. Throws inputError with `what`.
double lengthOf(const std::string& quantity, const std::string& what);

}  // namespace aeronc::kb
