// A small .xlsx writer for the browser tests, the same as tests/support/xlsx.rs writes for the
// core's: one sheet of text and numbers, its strings shared as the spreadsheets that forms export
// to write them, in a ZIP archive whose entries are stored.

const HEAD = '<?xml version="1.0" encoding="UTF-8" standalone="yes"?>';
const MAIN = 'http://schemas.openxmlformats.org/spreadsheetml/2006/main';
const RELS = 'http://schemas.openxmlformats.org/package/2006/relationships';
const DOC = 'http://schemas.openxmlformats.org/officeDocument/2006/relationships';

const xmlText = (s) => s.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;');

/** The bytes of an .xlsx workbook whose one sheet holds `rows` (arrays of strings and numbers). */
export function xlsx(rows) {
  const strings = [];
  let sheet = `${HEAD}<worksheet xmlns="${MAIN}"><sheetData>`;
  rows.forEach((row, r) => {
    sheet += `<row r="${r + 1}">`;
    row.forEach((cell, c) => {
      const at = `${String.fromCharCode(65 + c)}${r + 1}`;
      if (typeof cell === 'number') sheet += `<c r="${at}"><v>${cell}</v></c>`;
      else {
        let i = strings.indexOf(cell);
        if (i < 0) i = strings.push(cell) - 1;
        sheet += `<c r="${at}" t="s"><v>${i}</v></c>`;
      }
    });
    sheet += '</row>';
  });
  sheet += '</sheetData></worksheet>';
  const shared = strings.map((s) => `<si><t xml:space="preserve">${xmlText(s)}</t></si>`).join('');
  const part = (name, type) => `<Override PartName="${name}" ContentType="application/vnd.openxmlformats-officedocument.spreadsheetml.${type}+xml"/>`;
  return stored([
    [
      '[Content_Types].xml',
      `${HEAD}<Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types"><Default Extension="rels" ContentType="application/vnd.openxmlformats-package.relationships+xml"/><Default Extension="xml" ContentType="application/xml"/>${part('/xl/workbook.xml', 'sheet.main')}${part('/xl/worksheets/sheet1.xml', 'worksheet')}${part('/xl/sharedStrings.xml', 'sharedStrings')}</Types>`,
    ],
    ['_rels/.rels', `${HEAD}<Relationships xmlns="${RELS}"><Relationship Id="rId1" Type="${DOC}/officeDocument" Target="xl/workbook.xml"/></Relationships>`],
    [
      'xl/workbook.xml',
      `${HEAD}<workbook xmlns="${MAIN}" xmlns:r="${DOC}"><sheets><sheet name="Form Responses 1" sheetId="1" r:id="rId1"/></sheets></workbook>`,
    ],
    [
      'xl/_rels/workbook.xml.rels',
      `${HEAD}<Relationships xmlns="${RELS}"><Relationship Id="rId1" Type="${DOC}/worksheet" Target="worksheets/sheet1.xml"/><Relationship Id="rId2" Type="${DOC}/sharedStrings" Target="sharedStrings.xml"/></Relationships>`,
    ],
    ['xl/worksheets/sheet1.xml', sheet],
    ['xl/sharedStrings.xml', `${HEAD}<sst xmlns="${MAIN}" count="${strings.length}" uniqueCount="${strings.length}">${shared}</sst>`],
  ]);
}

function crc32(bytes) {
  let crc = ~0;
  for (const b of bytes) {
    crc ^= b;
    for (let k = 0; k < 8; k++) crc = (crc >>> 1) ^ (0xedb88320 & -(crc & 1));
  }
  return ~crc >>> 0;
}

/** A ZIP archive of `files` ([name, text] pairs), each stored (not compressed). */
function stored(files) {
  const out = [];
  const central = [];
  let offset = 0;
  for (const [name, text] of files) {
    const body = Buffer.from(text, 'utf8');
    const fileName = Buffer.from(name, 'utf8');
    // Version needed, flags, method (stored), time, date, CRC, sizes, name length, extra length.
    const common = Buffer.alloc(26);
    common.writeUInt16LE(20, 0);
    common.writeUInt16LE(0x21, 8); // 1980-01-01
    common.writeUInt32LE(crc32(body), 10);
    common.writeUInt32LE(body.length, 14);
    common.writeUInt32LE(body.length, 18);
    common.writeUInt16LE(fileName.length, 22);
    const local = Buffer.concat([Buffer.from([0x50, 0x4b, 0x03, 0x04]), common, fileName, body]);
    // Comment length, disk, internal and external attributes, then the local header's offset.
    const tail = Buffer.alloc(14);
    tail.writeUInt32LE(offset, 10);
    central.push(Buffer.concat([Buffer.from([0x50, 0x4b, 0x01, 0x02, 20, 0]), common, tail, fileName]));
    out.push(local);
    offset += local.length;
  }
  const dir = Buffer.concat(central);
  const end = Buffer.alloc(22);
  end.writeUInt32LE(0x06054b50, 0);
  end.writeUInt16LE(files.length, 8);
  end.writeUInt16LE(files.length, 10);
  end.writeUInt32LE(dir.length, 12);
  end.writeUInt32LE(offset, 16);
  return Buffer.concat([...out, dir, end]);
}
